# Two entry points on a fresh machine:
#   make demo   builds toonmesh into .venv and runs the main job
#   make test   builds it with the peer libraries and runs every test (Rust and Python)
# and: make docs (the documentation site, into site/), make wheel (an abi3 wheel, into
# target/wheels/), make notebook (JupyterLab on the quickstart), make stubs (the core's type stub,
# written from its description of the settings classes), make bench.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
WHEELS := target/wheels

# pip quiet while maturin installs an extra's packages: it hands pip every extra's packages with
# their markers, and pip would print a line for each one it skips or finds already there
export PIP_QUIET := 1
# MkDocs' theme prints a notice on every build otherwise
export NO_MKDOCS_2_WARNING := 1

.PHONY: demo test bench docs wheel stubs notebook sysdeps sysdeps-test build build-test clean

sysdeps:
	@PYTHON=$(PYTHON) bash scripts/system-deps.sh

# both rendering stacks and Chromium, for the tests
sysdeps-test:
	@PYTHON=$(PYTHON) bash scripts/system-deps.sh --test

$(BIN)/maturin:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --upgrade pip
	$(BIN)/python -m pip install "maturin>=1.9.4,<2.0"

# the io extra: trimesh (mesh files) and tqdm (progress bars) for the toonmesh command
build: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -E io

# the test extra (the peer libraries, pytest, Playwright) and the docs extra (MkDocs)
build-test: sysdeps-test $(BIN)/maturin
	$(BIN)/maturin develop --release -E test,docs

# The wheel, from the build above: the same cargo build (same interpreter, profile and
# features), so it only packs it. abi3: one wheel for CPython 3.9 and newer; maturin tags it with
# the oldest manylinux its symbols allow.
wheel: $(BIN)/maturin
	rm -f $(WHEELS)/toonmesh-*.whl
	$(BIN)/maturin build --release -i $(BIN)/python --out $(WHEELS)

# the notebook extra: JupyterLab and the viewer's widget (anywidget, ipywidgets)
notebook: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -E notebook
	$(BIN)/jupyter lab notebooks/quickstart.ipynb

demo: build
	$(BIN)/python -m toonmesh demo

# The Rust tests without Python: --lib builds only the unit tests (the crate has no doc tests
# or integration tests), on the dependencies the extension's build compiled (Cargo.toml's
# dev-dependencies keep their features the same). The wheel is for tests/test_wheel.py.
test: build-test wheel
	cargo test --release --no-default-features --lib
	$(BIN)/python -m pytest -q

bench: build-test
	$(BIN)/python -m toonmesh.bench all

docs: build-test
	$(BIN)/python -m mkdocs build
	@echo "open site/index.html"

clean:
	rm -rf $(VENV) target site

stubs: build-test
	$(BIN)/python scripts/stubs.py
