# pm2dof: `make demo` runs the main job, `make test` the tests; both set up .venv themselves.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
MODEL  ?= pm2dof/models/shang2010.toml
STAMP  := $(VENV)/.installed-stamp
OUT    ?= out

# one compiled library per shipped model: pm2dof/generated/<name>/lib<name>.so
MODEL_DIRS := $(patsubst %/manifest.json,%,$(wildcard pm2dof/generated/*/manifest.json))
LIBS := $(foreach d,$(MODEL_DIRS),$(d)/lib$(notdir $(d)).so)

.PHONY: install derive derive-all libs test test-quick test-slow lint docs check-install dist demo bench c-example embedded clean help

help:
	@echo "make demo     set up .venv (what the demo needs), build, reproduce the paper's experiment (Table 3, figures)"
	@echo "make test     set up .venv, build, run the test suite (not the tests marked slow)"
	@echo "make test-quick  the inner loop: the suite without the modules marked long"
	@echo "make test-slow  the tests marked slow: full-size studies, C builds, re-derivation (CI runs it)"
	@echo "make lint     ruff check pm2dof tests (pyflakes, import order, bugbear; pyproject.toml)"
	@echo "make derive   re-derive $(MODEL) into pm2dof/generated/<name>/ and compile it (MODEL=path)"
	@echo "make derive-all  re-derive every shipped model (after a change to pm2dof/derive/)"
	@echo "make dist     build the sdist and the wheel into dist/"
	@echo "make check-install  build the wheel, install it in a fresh venv outside the checkout, smoke-test it"
	@echo "make docs     build the documentation site into site/ (mkdocs build --strict)"
	@echo "make bench    controller step-time benchmark"
	@echo "make c-example  standalone C: NA against the compiled plant, paced at 2 ms"
	@echo "make embedded   pm2dof export of $(MODEL) cross-compiled for Cortex-M4F and M7, run under QEMU (MODEL=name or path)"
	@echo "make install  only create .venv, install pm2dof (editable) with the [dev] tools and compile every model's C (in parallel)"

# two stamps: $(STAMP) is pm2dof with what `make demo` needs (the runtime: NumPy, Matplotlib,
# tqdm; the [studies] and [design] extras: Dask, pyarrow and pymoo for the demo's robustness and
# design studies); $(DEV_STAMP) adds the [dev] extra (tests, SymPy and CasADi, docs, the bench's
# peers Pinocchio and MuJoCo: over 1 GB) for make test, install, lint, docs and bench.
# `pip install -e` compiles no model here (PM2DOF_BUILD_MODELS=none, setup.py): the rules below
# compile the libraries a target needs, all processors at once (make -j)
DEV_STAMP := $(VENV)/.installed-dev-stamp
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

$(STAMP): pyproject.toml setup.py pm2dof/core/_cbind.c pm2dof/core/_cbind_api.h \
          pm2dof/planning/_pathc.c pm2dof/planning/_passes.c pm2dof/planning/_buffers.h
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	PM2DOF_BUILD_MODELS=none $(PY) -m pip install --quiet -e '.[studies,design]'
	touch $@

$(DEV_STAMP): $(STAMP)
	PM2DOF_BUILD_MODELS=none $(PY) -m pip install --quiet -e '.[dev]'
	touch $@

# $(STAMP) is order-only: a newer stamp (pyproject.toml edited) must not compile them all again;
# make -j runs the libraries side by side, so each runs one compiler (PM2DOF_BUILD_JOBS=1)
# build.py and csplit.py too: a library compiled with other flags is compiled again (its build
# record's flags, build.library_is_fresh); one whose record matches is only touched
define LIB_RULE
$(1)/lib$(notdir $(1)).so: $(1)/$(notdir $(1)).c pm2dof/core/build.py pm2dof/core/csplit.py | $(STAMP)
	PM2DOF_BUILD_JOBS=1 $(PY) pm2dof/core/build.py $$< $$@
endef
$(foreach d,$(MODEL_DIRS),$(eval $(call LIB_RULE,$(d))))

libs: $(LIBS)

# the libraries `pm2dof demo` loads: the paper's robot (its experiment, maps and robustness
# study) and its [design] twin (the quick design study); any other is compiled on first use
DEMO_LIBS := pm2dof/generated/shang2010/libshang2010.so \
             pm2dof/generated/shang2010_design/libshang2010_design.so

install: $(DEV_STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) libs

derive: $(DEV_STAMP)
	$(VENV)/bin/pm2dof derive $(MODEL)

derive-all: $(DEV_STAMP)
	for m in pm2dof/models/*.toml; do $(VENV)/bin/pm2dof derive $$m || exit 1; done

# -n auto: one pytest worker per core; --dist loadscope keeps a module's tests (and its
# module-scoped fixtures: built models, derivations, studies) on one worker; tests/conftest.py
# (pytest_xdist_make_scheduler) hands out the modules marked long first and keeps the modules
# that share one SymPy derivation per model (tests/derivations.py) on one worker.
# PYTHONDONTWRITEBYTECODE cleared: both workers and the ~100 Python processes the tests start
# (CLI runs, Dask workers, import checks) reuse the bytecode of pm2dof and of the tests (pytest's
# rewritten asserts) that the first one compiled, instead of compiling it again (__pycache__/
# is git-ignored)
test: install
	PYTHONDONTWRITEBYTECODE= $(PY) -m pytest -q -n auto --dist loadscope

# the inner loop: make test without the modules marked long (pytest.mark.long: over 1.5 s
# each; tests/conftest.py does not even import them), on every core as make test
test-quick: install
	PYTHONDONTWRITEBYTECODE= $(PY) -m pytest -q -n auto --dist loadscope -m 'not slow and not long'

# the tests marked slow (pyproject.toml deselects them from make test): every shipped study and
# `pm2dof study bench` at full size, the exported C projects' builds, a full re-derivation, the
# Dask cluster tests, the pinned --json of every command (a study starts a
# 2-worker Dask cluster; two pytest workers). CI runs it after make test
test-slow: install
	PYTHONDONTWRITEBYTECODE= $(PY) -m pytest -q -n auto --dist loadscope -m slow

# pyflakes (F), import order (I), bugbear (B): [tool.ruff] in pyproject.toml
lint: $(DEV_STAMP)
	$(VENV)/bin/ruff check pm2dof tests

# the documentation site: docs/*.md and the docstrings, warnings are errors (mkdocs.yml); the
# docstrings' Sphinx roles become cross-links of the API page (docs/_ext/sphinx_roles.py).
# NO_MKDOCS_2_WARNING silences the Material theme's banner about MkDocs 2 (pinned < 2).
docs: $(DEV_STAMP)
	NO_MKDOCS_2_WARNING=1 $(VENV)/bin/mkdocs build --strict --site-dir site
	! grep -l -E ':(func|class|meth|attr|mod|data|exc):|autoref |&lt;autoref' site/api.html || \
		{ echo "make docs: Sphinx roles or autoref markup left in site/api.html (docs/_ext/sphinx_roles.py)"; exit 1; }

# the wheel and sdist need only the build frontend: `python -m build` installs the backend
# ([build-system] requires: setuptools, wheel) into an isolated environment of its own
BUILD_VENV  := .venv-build
BUILD_STAMP := $(BUILD_VENV)/.installed-stamp

$(BUILD_STAMP):
	test -x $(BUILD_VENV)/bin/python || $(PYTHON) -m venv $(BUILD_VENV)
	$(BUILD_VENV)/bin/python -m pip install --quiet 'build>=1.0'
	touch $@

dist: $(BUILD_STAMP)
	rm -rf dist
	$(BUILD_VENV)/bin/python -m build --outdir dist .

check-install: dist
	bash tests/install/smoke.sh dist

demo: $(STAMP)
	@$(MAKE) --no-print-directory -j$(JOBS) $(DEMO_LIBS)
	$(VENV)/bin/pm2dof demo --out $(OUT)

bench: install
	$(VENV)/bin/pm2dof bench

c-example: install
	$(MAKE) -C examples/c run

# pm2dof export's project of $(MODEL) (any model: MODEL=rrr4_platform, or a model file whose
# code is derived) cross-compiled for a Cortex-M4F and a Cortex-M7 (single and double), run
# under QEMU against the host build (docs/deploying.md): `pm2dof export MODEL --embedded`, which
# prints the table and writes $(EMBEDDED_OUT)/results.json. The Debian packages are installed
# when missing and this user may (root, or password-less sudo); otherwise it says what to install.
EMBEDDED_PKGS := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
EMBEDDED_OUT  ?= build/embedded
embedded: install
	@have() { command -v arm-none-eabi-gcc >/dev/null && command -v qemu-system-arm >/dev/null \
	    && test -f "$$(arm-none-eabi-gcc -print-file-name=libc.a)"; }; \
	if ! have; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $(EMBEDDED_PKGS); \
	  elif command -v apt-get >/dev/null && sudo -n true 2>/dev/null; then \
	    sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $(EMBEDDED_PKGS); \
	  fi; \
	  have || { echo "make embedded needs arm-none-eabi-gcc with newlib and qemu-system-arm;" \
	    "install them (Debian/Ubuntu: sudo apt-get install $(EMBEDDED_PKGS))"; exit 1; }; \
	fi
	@mkdir -p $(EMBEDDED_OUT)
	$(VENV)/bin/pm2dof export $(MODEL) --embedded --out $(EMBEDDED_OUT)

clean:
	rm -rf $(VENV) $(BUILD_VENV) build dist pm2dof/*.so pm2dof/*/*.so pm2dof/generated/*/*.so pm2dof/generated/*/*.so.json $(OUT) site
