# pm2dof: `make demo` runs the main job, `make test` the tests; both set up .venv themselves.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
MODEL  ?= models/shang2010.toml
STAMP  := $(VENV)/.installed-stamp
OUT    ?= out

# one compiled library per generated model folder: generated/<name>/lib<name>.so
MODEL_DIRS := $(patsubst %/manifest.json,%,$(wildcard generated/*/manifest.json))
LIBS := $(foreach d,$(MODEL_DIRS),$(d)/lib$(notdir $(d)).so)

.PHONY: install derive derive-all libs test demo bench c-example clean help

help:
	@echo "make demo     set up .venv, build, reproduce the paper's experiment (Table 3, figures)"
	@echo "make test     set up .venv, build, run the test suite"
	@echo "make derive   re-derive $(MODEL) into generated/<name>/ and compile it (MODEL=path)"
	@echo "make derive-all  re-derive every models/*.toml (after a change to derive/)"
	@echo "make bench    controller step-time benchmark"
	@echo "make c-example  standalone C: NA against the compiled plant, paced at 2 ms"
	@echo "make install  only create .venv, install pm2dof and compile the generated C"

$(STAMP): pyproject.toml setup.py pm2dof/core/_cbind.c
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $@

define LIB_RULE
$(1)/lib$(notdir $(1)).so: $(1)/$(notdir $(1)).c $(STAMP)
	$(PY) -m pm2dof.core.build $$< $$@
endef
$(foreach d,$(MODEL_DIRS),$(eval $(call LIB_RULE,$(d))))

libs: $(LIBS)

install: $(STAMP) libs

derive: $(STAMP)
	$(PY) -m derive $(MODEL)

derive-all: $(STAMP)
	for m in models/*.toml; do $(PY) -m derive $$m || exit 1; done

test: install
	$(PY) -m pytest -q

demo: install
	$(VENV)/bin/pm2dof demo --out $(OUT)

bench: install
	$(VENV)/bin/pm2dof bench

c-example: install
	$(MAKE) -C examples/c run

clean:
	rm -rf $(VENV) build pm2dof/*.so pm2dof/*/*.so generated/*/*.so $(OUT)
