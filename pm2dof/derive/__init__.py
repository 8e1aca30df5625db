# Build-time only: SymPy derivation of the model and CasADi export to C. Never imported at run time.
