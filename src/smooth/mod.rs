//! Mesh smoothing: Laplacian (uniform, cotangent, inverse distance), Taubin, HC and implicit.
