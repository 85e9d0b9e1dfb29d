# Two entry points on a fresh machine:
#   make demo   builds toonmesh into .venv and runs the main job
#   make test   builds it with the peer libraries and runs every test (Rust and Python)
#   make notebook  builds it with the notebook extra and opens the quickstart in JupyterLab
# and: make docs (the API reference from the docstrings, into docs/api/), make stubs (the core's
# type stub, written from its description of the settings classes)
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin

.PHONY: demo test bench docs stubs notebook sysdeps sysdeps-test build build-test clean

sysdeps:
	@bash scripts/system-deps.sh

# and Chromium, for the viewer's browser test
sysdeps-test:
	@bash scripts/system-deps.sh --test

$(BIN)/maturin:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q "maturin>=1.9.4,<2.0"

# the io extra: trimesh (mesh files) and tqdm (progress bars) for the toonmesh command
build: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -E io

build-test: sysdeps-test $(BIN)/maturin
	$(BIN)/maturin develop --release -q -E test

# the notebook extra: JupyterLab and the viewer's widget (anywidget, ipywidgets)
notebook: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -q -E notebook
	$(BIN)/jupyter lab notebooks/quickstart.ipynb

demo: build
	$(BIN)/python -m toonmesh demo

test: build-test
	cargo test --release --no-default-features
	$(BIN)/python -m pytest -q

bench: build-test
	$(BIN)/python -m toonmesh.bench all

docs: build-test
	$(BIN)/python docs/api_docs.py docs/api

clean:
	rm -rf $(VENV) target

stubs: build-test
	$(BIN)/python scripts/stubs.py
