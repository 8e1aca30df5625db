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

.PHONY: install derive derive-all libs test docs check-install dist demo bench c-example clean help

help:
	@echo "make demo     set up .venv, build, reproduce the paper's experiment (Table 3, figures)"
	@echo "make test     set up .venv, build, run the test suite"
	@echo "make derive   re-derive $(MODEL) into pm2dof/generated/<name>/ and compile it (MODEL=path)"
	@echo "make derive-all  re-derive every shipped model (after a change to pm2dof/derive/)"
	@echo "make dist     build the sdist and the wheel into dist/"
	@echo "make check-install  build the wheel, install it in a fresh venv outside the checkout, smoke-test it"
	@echo "make docs     build the documentation site into site/ (mkdocs build --strict)"
	@echo "make bench    controller step-time benchmark"
	@echo "make c-example  standalone C: NA against the compiled plant, paced at 2 ms"
	@echo "make install  only create .venv, install pm2dof (editable) and compile the generated C"

$(STAMP): pyproject.toml setup.py pm2dof/core/_cbind.c
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $@

define LIB_RULE
$(1)/lib$(notdir $(1)).so: $(1)/$(notdir $(1)).c $(STAMP)
	$(PY) pm2dof/core/build.py $$< $$@
endef
$(foreach d,$(MODEL_DIRS),$(eval $(call LIB_RULE,$(d))))

libs: $(LIBS)

install: $(STAMP) libs

derive: $(STAMP)
	$(VENV)/bin/pm2dof derive $(MODEL)

derive-all: $(STAMP)
	for m in pm2dof/models/*.toml; do $(VENV)/bin/pm2dof derive $$m || exit 1; done

# -n auto: one pytest worker per core; --dist loadscope keeps a module's tests (and its
# module-scoped fixtures: built models, derivations, studies) on one worker
test: install
	$(PY) -m pytest -q -n auto --dist loadscope

# the documentation site: docs/*.md and the docstrings, warnings are errors (mkdocs.yml).
# NO_MKDOCS_2_WARNING silences the Material theme's banner about MkDocs 2 (pinned < 2).
docs: $(STAMP)
	NO_MKDOCS_2_WARNING=1 $(VENV)/bin/mkdocs build --strict --site-dir site
	! grep -l -E ':(func|class|meth|attr|mod|data|exc):' site/api.html || \
		{ echo "make docs: Sphinx roles left in site/api.html (docs/_ext/sphinx_roles.py)"; exit 1; }

dist: $(STAMP)
	rm -rf dist
	$(PY) -m build --outdir dist .

check-install: dist
	bash tests/install/smoke.sh dist

demo: install
	$(VENV)/bin/pm2dof demo --out $(OUT)

bench: install
	$(VENV)/bin/pm2dof bench

c-example: install
	$(MAKE) -C examples/c run

clean:
	rm -rf $(VENV) build dist pm2dof/*.so pm2dof/*/*.so pm2dof/generated/*/*.so pm2dof/generated/*/*.so.json $(OUT) site
