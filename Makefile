# Two entry points on a fresh machine:
#   make demo   builds toonmesh into .venv and runs the main job
#   make test   builds it with the peer libraries and runs every test (Rust and Python)
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin

.PHONY: demo test bench sysdeps build build-test clean

sysdeps:
	@bash scripts/system-deps.sh

$(BIN)/maturin:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	$(BIN)/pip install -q "maturin>=1.9.4,<2.0"

build: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -q

build-test: sysdeps $(BIN)/maturin
	$(BIN)/maturin develop --release -q -E test

demo: build
	$(BIN)/python -m toonmesh demo

test: build-test
	cargo test --release --no-default-features
	$(BIN)/python -m pytest -q

bench: build-test
	$(BIN)/python -m toonmesh.bench all

clean:
	rm -rf $(VENV) target
