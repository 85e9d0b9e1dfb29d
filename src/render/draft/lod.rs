//! A coarse copy of a large mesh for drafts drawn smaller than the exact frame, where a triangle
//! covers less than a pixel and a browser drawing on the CPU spends its time on vertices and
//! triangles nobody sees: vertex clustering on a grid, the cell grown until the copy has at most
//! the faces asked for.
//!
//! The vertices in one cell that face the same way (their normals on the same side of the cell's
//! mean normal) share one position and normal, their mean: so a smooth surface stays closed,
//! whatever its curvature, while sides that face away from each other (the two sides of a thin
//! sheet) stay apart. Among them, those whose albedo (colour and texture coordinates, to an
//! eighth) is the same become one vertex, with the albedo of the one nearest the mean: seams of
//! the texture or the colours stay seams, without a crack. A face whose corners meet in fewer
//! than three vertices goes; so does a second face over the same three.
//! The copy works on the buffers as uploaded, whatever else their vertices hold (copied from the
//! nearest vertex).

use std::collections::{HashMap, HashSet};

/// Where a vertex's position and normal lie in the vertex buffer's records.
#[derive(Clone, Copy, Debug)]
pub struct PositionLayout {
    pub stride: usize,
    /// The byte offsets of the position's and the normal's three f32s.
    pub position: usize,
    pub normal: Option<usize>,
}

/// A mesh as uploaded: its vertex buffer, its albedo buffer (with its stride) if it has one,
/// and its faces (u32 indices; None: the vertices in order, three a face).
pub struct Uploaded<'a> {
    pub vertices: &'a [u8],
    pub layout: PositionLayout,
    pub albedo: Option<(&'a [u8], usize)>,
    pub indices: Option<&'a [u32]>,
    /// The number of indices (or vertices, without indices) drawn.
    pub count: usize,
}

/// The coarse copy: its vertex and albedo buffers (the layouts of the mesh's own) and its faces.
#[derive(Clone, Debug, PartialEq)]
pub struct Coarse {
    pub vertices: Vec<u8>,
    pub albedo: Option<Vec<u8>>,
    pub indices: Vec<u32>,
}

fn f32_at(bytes: &[u8], at: usize) -> f32 {
    f32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
}

fn vec3_at(bytes: &[u8], at: usize) -> [f64; 3] {
    [0, 4, 8].map(|k| f32_at(bytes, at + k) as f64)
}

/// A vertex's albedo to an eighth (colours and texture coordinates), hashed.
fn albedo_key(record: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for k in (0..record.len() / 4 * 4).step_by(4) {
        let q = (f32_at(record, k) * 8.0).floor();
        let q = if q.is_finite() { q as i64 } else { 0 };
        h = (h ^ q as u64).wrapping_mul(0x100_0000_01b3);
    }
    h
}

/// The mesh's vertices over cells of `cell`: each vertex's cluster and the clusters' groups
/// (the vertices of a cell that face the same way, which share a position).
struct Clusters {
    of: Vec<u32>,
    group: Vec<u32>,
    groups: usize,
}

/// The faces of the mesh over clusters of `cell`: the clusters and the faces kept.
fn cluster(m: &Uploaded, faces: &[[u32; 3]], low: [f64; 3], cell: f64) -> (Clusters, Vec<[u32; 3]>) {
    let n = m.vertices.len() / m.layout.stride;
    let record = |v: usize| &m.vertices[v * m.layout.stride..];
    let cell_of = |v: usize| {
        let p = vec3_at(record(v), m.layout.position);
        [0, 1, 2].map(|k| ((p[k] - low[k]) / cell).floor() as i64)
    };
    let normal = |v: usize| m.layout.normal.map_or([0.0; 3], |at| vec3_at(record(v), at));
    let used: Vec<usize> = {
        let mut seen = vec![false; n];
        faces
            .iter()
            .flatten()
            .map(|&v| v as usize)
            .filter(|&v| !std::mem::replace(&mut seen[v], true))
            .collect()
    };
    // each cell's mean normal: the way its vertices face, mostly
    let mut facing: HashMap<[i64; 3], [f64; 3]> = HashMap::new();
    for &v in &used {
        let (sum, nr) = (facing.entry(cell_of(v)).or_default(), normal(v));
        for k in 0..3 {
            sum[k] += nr[k];
        }
    }
    let mut groups: HashMap<([i64; 3], bool), u32> = HashMap::new();
    let mut ids: HashMap<(u32, u64), u32> = HashMap::new();
    let (mut of, mut group) = (vec![u32::MAX; n], Vec::new());
    for &v in &used {
        let c = cell_of(v);
        let (mean, nr) = (facing[&c], normal(v));
        let away = mean[0] * nr[0] + mean[1] * nr[1] + mean[2] * nr[2] < 0.0;
        let next = groups.len() as u32;
        let g = *groups.entry((c, away)).or_insert(next);
        let a = m.albedo.map_or(0, |(bytes, stride)| albedo_key(&bytes[v * stride..(v + 1) * stride]));
        let next = ids.len() as u32;
        of[v] = *ids.entry((g, a)).or_insert_with(|| {
            group.push(g);
            next
        });
    }
    let mut seen = HashSet::new();
    let mut kept = Vec::new();
    for f in faces {
        let g = f.map(|v| of[v as usize]);
        if g[0] == g[1] || g[1] == g[2] || g[0] == g[2] {
            continue;
        }
        let mut key = g;
        key.sort_unstable();
        if seen.insert(key) {
            kept.push(g);
        }
    }
    (Clusters { of, group, groups: groups.len() }, kept)
}

/// The coarse copy of `m` with at most `most_faces` faces, or None where the mesh has no more
/// than that or clustering cannot bring it down to that.
pub fn coarse(m: &Uploaded, most_faces: usize) -> Option<Coarse> {
    let stride = m.layout.stride;
    let n = m.vertices.len() / stride;
    let faces: Vec<[u32; 3]> = match m.indices {
        Some(ix) => ix[..m.count.min(ix.len())].chunks_exact(3).map(|f| [f[0], f[1], f[2]]).collect(),
        None => (0..(m.count.min(n) / 3) as u32).map(|f| [3 * f, 3 * f + 1, 3 * f + 2]).collect(),
    };
    if faces.len() <= most_faces || most_faces == 0 || faces.iter().flatten().any(|&v| v as usize >= n) {
        return None;
    }
    let at = |v: u32| vec3_at(&m.vertices[v as usize * stride..], m.layout.position);
    let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let mut area = 0.0;
    for f in &faces {
        let [a, b, c] = f.map(at);
        for p in [a, b, c] {
            for k in 0..3 {
                low[k] = low[k].min(p[k]);
                high[k] = high[k].max(p[k]);
            }
        }
        let (u, w) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
        let x = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
        area += 0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    }
    if !(area > 0.0 && area.is_finite()) {
        return None;
    }
    // a closed surface has about twice as many faces as vertices: cells of about the area a
    // vertex of the copy stands for, grown until the copy is small enough
    let mut cell = (2.0 * area / most_faces as f64).sqrt();
    let (made, kept) = (0..16).find_map(|_| {
        let made = cluster(m, &faces, low, cell);
        cell *= 1.25;
        (made.1.len() <= most_faces).then_some(made)
    })?;
    let Clusters { of, group, groups } = made;
    let clusters = group.len();
    // each group: the mean position and normal; each cluster its group's, and the rest from its
    // vertex nearest that mean
    let mut sum = vec![([0.0f64; 3], [0.0f64; 3], 0u32); groups];
    for (v, &c) in of.iter().enumerate().filter(|(_, &c)| c != u32::MAX) {
        let record = &m.vertices[v * stride..];
        let s = &mut sum[group[c as usize] as usize];
        let p = vec3_at(record, m.layout.position);
        let nr = m.layout.normal.map_or([0.0; 3], |at| vec3_at(record, at));
        for k in 0..3 {
            s.0[k] += p[k];
            s.1[k] += nr[k];
        }
        s.2 += 1;
    }
    let mean = |c: usize| {
        let g = group[c] as usize;
        sum[g].0.map(|x| x / sum[g].2 as f64)
    };
    let mut nearest = vec![(f64::INFINITY, 0usize); clusters];
    for (v, &c) in of.iter().enumerate().filter(|(_, &c)| c != u32::MAX) {
        let (p, q) = (vec3_at(&m.vertices[v * stride..], m.layout.position), mean(c as usize));
        let d = (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>();
        if d < nearest[c as usize].0 {
            nearest[c as usize] = (d, v);
        }
    }
    let mut vertices = Vec::with_capacity(clusters * stride);
    let mut albedo = m.albedo.map(|(_, s)| Vec::with_capacity(clusters * s));
    for (c, &(_, v)) in nearest.iter().enumerate() {
        let mut record = m.vertices[v * stride..(v + 1) * stride].to_vec();
        let put = |record: &mut Vec<u8>, at: usize, x: [f64; 3]| {
            for k in 0..3 {
                record[at + 4 * k..at + 4 * k + 4].copy_from_slice(&(x[k] as f32).to_le_bytes());
            }
        };
        put(&mut record, m.layout.position, mean(c));
        if let Some(at) = m.layout.normal {
            let s = sum[group[c] as usize].1;
            let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
            if len > 0.0 {
                put(&mut record, at, s.map(|x| x / len));
            }
        }
        vertices.extend_from_slice(&record);
        if let (Some(out), Some((bytes, s))) = (albedo.as_mut(), m.albedo) {
            out.extend_from_slice(&bytes[v * s..(v + 1) * s]);
        }
    }
    Some(Coarse { vertices, albedo, indices: kept.into_iter().flatten().collect() })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sphere of `rings` x `segments` quads (position and normal, 24 bytes a vertex).
    fn sphere(rings: u32, segments: u32) -> (Vec<u8>, Vec<u32>) {
        let mut bytes = Vec::new();
        for r in 0..=rings {
            for s in 0..segments {
                let (t, p) = (
                    std::f32::consts::PI * r as f32 / rings as f32,
                    std::f32::consts::TAU * s as f32 / segments as f32,
                );
                let n = [t.sin() * p.cos(), t.sin() * p.sin(), t.cos()];
                for x in n.iter().chain(n.iter()) {
                    bytes.extend_from_slice(&x.to_le_bytes());
                }
            }
        }
        let mut ix = Vec::new();
        for r in 0..rings {
            for s in 0..segments {
                let (a, b) = (r * segments + s, r * segments + (s + 1) % segments);
                ix.extend([a, a + segments, b, b, a + segments, b + segments]);
            }
        }
        (bytes, ix)
    }

    const LAYOUT: PositionLayout = PositionLayout { stride: 24, position: 0, normal: Some(12) };

    /// An indexed mesh of positions and normals, without albedo.
    fn indexed<'a>(vertices: &'a [u8], indices: &'a [u32]) -> Uploaded<'a> {
        Uploaded { vertices, layout: LAYOUT, albedo: None, indices: Some(indices), count: indices.len() }
    }

    #[test]
    fn a_large_mesh_comes_down_to_the_faces_asked_for_and_keeps_its_shape() {
        let (vertices, indices) = sphere(120, 160);
        let m = indexed(&vertices, &indices);
        let c = coarse(&m, 4000).expect("a coarse copy");
        let faces = c.indices.len() / 3;
        assert!(faces <= 4000 && faces > 1000, "{faces} faces");
        let n = c.vertices.len() / 24;
        assert!(c.indices.iter().all(|&v| (v as usize) < n));
        for v in 0..n {
            let (p, nr) = (vec3_at(&c.vertices, 24 * v), vec3_at(&c.vertices, 24 * v + 12));
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            assert!((r - 1.0).abs() < 0.05, "a vertex {r} from the centre");
            let len = (nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-4 && (p[0] * nr[0] + p[1] * nr[1] + p[2] * nr[2]) / r > 0.95);
        }
    }

    #[test]
    fn a_smooth_closed_surface_stays_closed() {
        // no crack where the normals turn across a cell: every edge of the copy has two faces
        let (vertices, indices) = sphere(120, 160);
        let c = coarse(&indexed(&vertices, &indices), 3000).expect("a coarse copy");
        let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
        for f in c.indices.chunks_exact(3) {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        let open = edges.values().filter(|&&n| n == 1).count();
        assert_eq!(open, 0, "{open} of {} edges have one face", edges.len());
    }

    #[test]
    fn a_small_mesh_has_no_copy() {
        let (vertices, indices) = sphere(8, 8);
        let m = indexed(&vertices, &indices);
        assert_eq!(coarse(&m, 10_000), None);
    }

    #[test]
    fn the_albedo_follows_and_its_seams_stay_apart() {
        let (vertices, indices) = sphere(60, 80);
        // a colour (4 floats) and texture coordinates (2): u jumps at x = 0
        let n = vertices.len() / 24;
        let mut albedo = Vec::new();
        for v in 0..n {
            let p = vec3_at(&vertices, 24 * v);
            for x in [1.0f32, 0.5, 0.25, 1.0, if p[0] < 0.0 { 0.0 } else { 0.9 }, 0.5] {
                albedo.extend_from_slice(&x.to_le_bytes());
            }
        }
        let m = Uploaded {
            vertices: &vertices,
            layout: LAYOUT,
            albedo: Some((&albedo, 24)),
            indices: Some(&indices),
            count: indices.len(),
        };
        let c = coarse(&m, 2000).expect("a coarse copy");
        let a = c.albedo.expect("its albedo");
        assert_eq!(a.len() / 24, c.vertices.len() / 24);
        for v in 0..a.len() / 24 {
            let (p, u) = (vec3_at(&c.vertices, 24 * v), f32_at(&a, 24 * v + 16));
            assert_eq!(f32_at(&a, 24 * v + 4), 0.5);
            // a vertex by the seam takes the side its position lies on, to a cell
            if p[0].abs() > 0.1 {
                assert_eq!(u, if p[0] < 0.0 { 0.0 } else { 0.9 }, "{p:?}");
            }
        }
    }

    #[test]
    fn faces_without_indices_become_indexed() {
        let (vertices, indices) = sphere(60, 80);
        let mut flat = Vec::new();
        for &v in &indices {
            flat.extend_from_slice(&vertices[24 * v as usize..24 * v as usize + 24]);
        }
        let m =
            Uploaded { vertices: &flat, layout: LAYOUT, albedo: None, indices: None, count: indices.len() };
        let c = coarse(&m, 3000).expect("a coarse copy");
        assert!(c.indices.len() / 3 <= 3000 && !c.indices.is_empty());
        assert!(c.vertices.len() / 24 < flat.len() / 24 / 4);
    }
}
