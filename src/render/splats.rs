//! A point cloud drawn as splats: one triangle per point, in the plane of its normal, around a
//! disc of the splat's radius, with texture coordinates that put the disc texture's round
//! alpha on it, so that the alpha cutoff cuts every triangle to its disc. The cloud is then a
//! mesh like any other (toon shading, materials, shadows, the geometry and depth targets work
//! on it unchanged); its record is marked as splats, so that the outlines ink it in image space
//! (its triangles' edges are no lines of the surface).

use crate::error::{Error, Result};
use crate::points::local::{neighbourhoods, Local};
use crate::render::albedo::{Albedo, Colors, Filter, Sampling, Texture, Wrap};
use crate::render::gpu_mesh::MeshNormals;
use crate::render::scene::MeshId;
use crate::render::Renderer;

/// The default splat radius in units of the mean distance from a point to its k-th nearest
/// neighbour: with 12 neighbours on a surface, about 1.7 times the mean spacing, which randomly
/// placed points need to cover it without holes (smaller splats leave gaps that image-space
/// ink marks as depth jumps).
pub const RADIUS_PER_REACH: f64 = 0.9;

/// The default splat radius of a cloud of no more points than the neighbours a reach counts (it
/// samples no surface to cover: its reach spans the cloud, and its splats would merge into a
/// blob), in units of the mean distance to the nearest neighbour: dots that do not overlap.
pub const SPARSE_RADIUS_PER_NEAREST: f64 = 0.4;

/// The side in texels of the disc texture.
const DISC_TEXELS: u32 = 64;

/// Texture coordinates are the splat's plane over [-2r, 2r] squared (the triangle's corners lie
/// at 2r from its point, the disc of radius r is inscribed in it): the disc is the texels
/// within this radius of the centre.
const DISC_UV_RADIUS: f32 = 0.25;

/// The alpha below which a splat's pixel is cut (the disc's edge, half way through its
/// antialiased rim).
pub const DISC_CUTOFF: f32 = 0.5;

/// Each splat's radius.
#[derive(Clone, Debug, PartialEq)]
pub enum Radius {
    /// `RADIUS_PER_REACH` times the cloud's mean reach.
    Spacing,
    All(f64),
    Each(Vec<f64>),
}

/// The disc texture: white, opaque within `DISC_UV_RADIUS` of the centre.
pub fn disc_texture() -> Texture {
    let n = DISC_TEXELS;
    let texels = (0..n * n)
        .map(|i| {
            let (x, y) = ((i % n) as f32 + 0.5, (i / n) as f32 + 0.5);
            let d = ((x / n as f32 - 0.5).powi(2) + (y / n as f32 - 0.5).powi(2)).sqrt();
            [255, 255, 255, if d <= DISC_UV_RADIUS { 255 } else { 0 }]
        })
        .collect();
    Texture::new(n, n, texels).expect("a square of DISC_TEXELS")
}

/// The splat mesh of a cloud: three vertices and one face per point.
pub struct SplatMesh {
    pub positions: Vec<[f64; 3]>,
    pub faces: Vec<[u32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub uv: Vec<[f32; 2]>,
}

/// Each point's radius, and its normal (the given one, else its neighbourhood's, from `k`
/// neighbours).
pub fn splat_frames(
    points: &[[f64; 3]],
    normals: Option<Vec<[f64; 3]>>,
    radius: &Radius,
    k: usize,
) -> Result<(Vec<[f64; 3]>, Vec<f64>)> {
    let local: Option<Vec<Local>> =
        (normals.is_none() || *radius == Radius::Spacing).then(|| neighbourhoods(points, k));
    let normals = match normals {
        Some(n) => n,
        None => local.as_ref().map_or_else(Vec::new, |l| l.iter().map(|x| x.normal).collect()),
    };
    let radii = match radius {
        Radius::All(r) => vec![*r; points.len()],
        Radius::Each(r) if r.len() == points.len() => r.clone(),
        Radius::Each(r) => {
            return Err(Error::invalid("radius", format!("expected {} radii, got {}", points.len(), r.len())))
        }
        Radius::Spacing => vec![spacing_radius(points, local.as_deref().unwrap_or(&[]), k); points.len()],
    };
    if let Some(bad) = radii.iter().find(|r| !(r.is_finite() && **r > 0.0)) {
        return Err(Error::invalid("radius", format!("must be finite and > 0, got {bad}")));
    }
    Ok((normals, radii))
}

/// `RADIUS_PER_REACH` times the mean reach of `k` neighbours (`SPARSE_RADIUS_PER_NEAREST` times
/// the mean nearest distance in a cloud of k points or fewer); for a cloud with no spacing (one
/// point, or all points at one place), a hundredth of its distance from the origin, else 1.
fn spacing_radius(points: &[[f64; 3]], local: &[Local], k: usize) -> f64 {
    let n = local.len().max(1) as f64;
    let mean = crate::parallel::deterministic_sum(local.len(), |i| local[i].reach / n);
    let nearest = crate::parallel::deterministic_sum(local.len(), |i| local[i].nearest / n);
    if points.len() <= k && nearest > 0.0 && nearest.is_finite() {
        return SPARSE_RADIUS_PER_NEAREST * nearest;
    }
    if mean > 0.0 && mean.is_finite() {
        return RADIUS_PER_REACH * mean;
    }
    let far = points.iter().map(|p| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()).fold(0.0, f64::max);
    if far > 0.0 {
        far * 0.01
    } else {
        1.0
    }
}

/// The splats of `points` with unit `normals` and `radii`: corner j of point i's triangle at
/// 2 r from it, at 90 + 120 j degrees in the plane (t, n x t), counter-clockwise about the
/// normal (its front side).
pub fn splat_mesh(points: &[[f64; 3]], normals: &[[f64; 3]], radii: &[f64]) -> SplatMesh {
    let n = points.len();
    let mut m = SplatMesh {
        positions: Vec::with_capacity(3 * n),
        faces: Vec::with_capacity(n),
        normals: Vec::with_capacity(3 * n),
        uv: Vec::with_capacity(3 * n),
    };
    let corners = [90.0f64, 210.0, 330.0].map(|d| (d.to_radians().cos(), d.to_radians().sin()));
    for i in 0..n {
        let (p, nn, r) = (points[i], normals[i], radii[i]);
        let (t, b) = tangents(nn);
        for (c, s) in corners {
            m.positions.push([0, 1, 2].map(|a| p[a] + 2.0 * r * (c * t[a] + s * b[a])));
            m.normals.push(nn.map(|x| x as f32));
            let half = 2.0 * DISC_UV_RADIUS;
            m.uv.push([0.5 + half * c as f32, 0.5 + half * s as f32]);
        }
        let v = 3 * i as u32;
        m.faces.push([v, v + 1, v + 2]);
    }
    m
}

/// Two unit vectors that make a right-handed frame (t, b, n) with the unit normal `n`.
fn tangents(n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    // the axis least along n
    let axis = if n[0].abs() <= n[1].abs() && n[0].abs() <= n[2].abs() {
        [1.0, 0.0, 0.0]
    } else if n[1].abs() <= n[2].abs() {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let t = cross(axis, n);
    let l = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
    let t = t.map(|x| x / l);
    (t, cross(n, t))
}

impl Renderer {
    /// Uploads a point cloud as splats (see the module) and returns its id: `normals` unit, one
    /// per point (None: estimated from `k` neighbours); `colors` linear RGBA, one per point
    /// (None: white; their alpha is not drawn).
    pub fn add_points(
        &self,
        points: &[[f64; 3]],
        normals: Option<Vec<[f64; 3]>>,
        colors: Option<Vec<[f32; 4]>>,
        radius: &Radius,
        k: usize,
    ) -> Result<MeshId> {
        crate::points::local::check_neighbours("k", k)?;
        if points.is_empty() {
            return Err(Error::invalid("positions", "a point cloud needs at least 1 point, got 0"));
        }
        crate::mesh::check_positions("positions", points)?;
        if let Some(n) = &normals {
            crate::error::as_many("normals", n.len(), ("points", points.len()))?;
        }
        if let Some(c) = &colors {
            crate::error::as_many("colors", c.len(), ("points", points.len()))?;
        }
        let (normals, radii) = crate::parallel::install(|| splat_frames(points, normals, radius, k))?;
        let mesh = splat_mesh(points, &normals, &radii);
        let albedo = Albedo {
            // opaque: the cutoff is the disc's shape, which a colour's alpha must not cut away
            colors: colors
                .map(|c| Colors::Vertex(c.iter().flat_map(|&[r, g, b, _]| [[r, g, b, 1.0]; 3]).collect())),
            uv: Some(mesh.uv),
            texture: Some(disc_texture()),
            sampling: Sampling {
                filter: Filter::Nearest,
                wrap: Wrap::Clamp,
                alpha_cutoff: Some(DISC_CUTOFF),
                alpha_blend: false,
            },
        };
        self.upload(&mesh.positions, mesh.faces, MeshNormals::Given(mesh.normals), Some(albedo), true)
            .map(|(id, _)| id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_splat_holds_its_disc_and_faces_its_normal() {
        let points = [[1.0, 2.0, 3.0], [0.0, 0.0, 0.0]];
        let normals = [[0.0, 0.0, 1.0], [0.6, 0.0, 0.8]];
        let m = splat_mesh(&points, &normals, &[0.5, 2.0]);
        for (i, f) in m.faces.iter().enumerate() {
            let [a, b, c] = f.map(|v| m.positions[v as usize]);
            let e1 = [0, 1, 2].map(|k| b[k] - a[k]);
            let e2 = [0, 1, 2].map(|k| c[k] - a[k]);
            let cr =
                [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
            let along = (0..3).map(|k| cr[k] * normals[i][k]).sum::<f64>();
            assert!(along > 0.0, "counter-clockwise about the normal");
            // the inscribed circle of a triangle with circumradius 2r has radius r
            let centre = [0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0);
            assert!((0..3).all(|k| (centre[k] - points[i][k]).abs() < 1e-12));
        }
        // the texture coordinates' disc is the splat's: r maps to DISC_UV_RADIUS
        let uv = m.uv[0];
        assert!(((uv[0] - 0.5).hypot(uv[1] - 0.5) - 2.0 * DISC_UV_RADIUS).abs() < 1e-6);
    }

    #[test]
    fn default_radius_follows_the_spacing() {
        let grid: Vec<[f64; 3]> = (0..400).map(|i| [(i % 20) as f64, (i / 20) as f64, 0.0]).collect();
        let small: Vec<[f64; 3]> = grid.iter().map(|p| p.map(|x| x * 1e-3)).collect();
        let (_, r) = splat_frames(&grid, None, &Radius::Spacing, 12).unwrap();
        let (_, s) = splat_frames(&small, None, &Radius::Spacing, 12).unwrap();
        assert!(r[0] > 1.0 && r[0] < 3.0, "{}", r[0]);
        assert!((s[0] - r[0] * 1e-3).abs() < 1e-9 * r[0]);
        let (_, one) = splat_frames(&[[0.0; 3]], None, &Radius::Spacing, 12).unwrap();
        assert_eq!(one, vec![1.0]);
    }

    #[test]
    fn a_sparse_cloud_draws_dots_that_do_not_overlap() {
        // a hexagon of side 2 around its centre (glTF's sample of points): every point's nearest
        // neighbour 2 away, its 12-neighbour reach across the cloud
        let mut hexagon = vec![[0.0; 3]];
        hexagon.extend((0..6).map(|j| {
            let a = j as f64 * std::f64::consts::FRAC_PI_3;
            [2.0 * a.cos(), 2.0 * a.sin(), 0.0]
        }));
        let (_, r) = splat_frames(&hexagon, None, &Radius::Spacing, 12).unwrap();
        assert!(r.iter().all(|x| (x - SPARSE_RADIUS_PER_NEAREST * 2.0).abs() < 1e-9), "{r:?}");
        assert!(2.0 * r[0] < 2.0, "neighbouring dots stay apart");
        // one point more than the neighbours: the spacing rule again
        let grid: Vec<[f64; 3]> = (0..13).map(|i| [(i % 4) as f64, (i / 4) as f64, 0.0]).collect();
        let (_, g) = splat_frames(&grid, None, &Radius::Spacing, 12).unwrap();
        assert!(g[0] > 1.0, "{}", g[0]);
    }

    #[test]
    fn the_disc_is_round() {
        let t = disc_texture();
        let opaque = t.texels.iter().filter(|x| x[3] == 255).count() as f64;
        let expected = std::f64::consts::PI * (DISC_UV_RADIUS as f64 * DISC_TEXELS as f64).powi(2);
        assert!((opaque / expected - 1.0).abs() < 0.05);
    }
}
