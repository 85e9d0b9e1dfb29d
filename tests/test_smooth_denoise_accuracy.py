"""Accuracy of the feature-preserving smoothers on generated noisy CAD parts (20,000 faces):
the mean angle between the result's face normals and the clean part's, in degrees.

Targets: at most 8 (bilateral) and 5 (guided) at light and medium noise (Gaussian 0.2 and 0.4
mean edge lengths, impulsive 1.0 on a tenth of the vertices), at most 12 and 10 at heavy noise
(Gaussian 0.7); always better than Taubin and pymeshlab's two-step smoothing with defaults."""

from __future__ import annotations

import numpy as np
import pytest

import toonmesh as tm
from toonmesh.bench import parts

from conftest import need

CASES = [("gaussian", 0.2, "light"), ("gaussian", 0.4, "medium"), ("gaussian", 0.7, "heavy"),
         ("impulsive", 1.0, "medium")]
TARGET = {"bilateral": {"light": 8, "medium": 8, "heavy": 12}, "guided": {"light": 5, "medium": 5, "heavy": 10}}


@pytest.fixture(scope="module", params=parts.PARTS)
def part(request):
    return request.param, parts.part(request.param, 20000)


def two_step(V, F):
    pymeshlab = need("pymeshlab")
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(V, F))
    ms.apply_coord_two_steps_smoothing()
    return ms.current_mesh().vertex_matrix()


@pytest.mark.parametrize("kind, level, strength", CASES)
def test_normal_error_meets_the_targets_and_beats_laplacian_and_two_step(part, kind, level, strength):
    name, (V, F) = part
    N = parts.noisy(V, F, level, kind, seed=1)
    error = {
        "bilateral": parts.normal_error(tm.smooth.bilateral(N, F), F, V),
        "guided": parts.normal_error(tm.smooth.guided(N, F), F, V),
        "taubin": parts.normal_error(tm.smooth.taubin(N, F), F, V),
        "two-step": parts.normal_error(two_step(N, F), F, V),
    }
    for method in ("bilateral", "guided"):
        assert error[method] <= TARGET[method][strength], (name, kind, level, error)
        assert error[method] < min(error["taubin"], error["two-step"]), (name, kind, level, error)
    assert error["guided"] < error["bilateral"] + 0.2, (name, kind, level, error)


def test_the_parts_have_sharp_creases_and_the_noise_its_level():
    for name in parts.PARTS:
        V, F = parts.part(name, 20000)
        n = parts.face_normals(V, F)
        assert 18000 < len(F) < 22000 and np.isfinite(n).all()
        N = parts.noisy(V, F, 0.4, seed=0)
        d = np.linalg.norm(N - V, axis=1) / parts.mean_edge_length(V, F)
        assert 0.37 < np.sqrt((d**2).mean()) < 0.43
        moved = parts.noisy(V, F, 1.0, "impulsive", seed=0)
        assert 0.08 < (np.abs(moved - V).max(axis=1) > 0).mean() < 0.12
