//! Every combination of the per-pixel effects (dithering fixed to the screen or to the surface,
//! hatching triplanar or along the field, the rim light) and the mesh's colour (none, per
//! vertex, a texture) builds its shading pipeline from the parts the effects declare, and a
//! small frame of each matches the effects' CPU references composed in the shader's order
//! (jitter, bands, each finish), on Vulkan and GL.
//!
//! The scene is a height field seen straight down through an orthographic camera, so that each
//! pixel's point, normal and stripe values are the linear interpolation of one triangle's
//! corners (found on the CPU, no rasteriser needed), and their change across a pixel that
//! triangle's gradient, as the GPU's quad derivatives take it (helper pixels extend the
//! triangle's plane). Band borders are hard (`band_antialias` off).

use glam::{DMat4, DVec4, Vec3};

use super::albedo::{Albedo, Colors, Texture};
use super::color::{linear_to_srgb8, to_linear};
use super::effects::dither::{Dither, DitherPattern, DitherSpace};
use super::effects::hatching::field::hatch_stripes;
use super::effects::hatching::{field_coverage, hatch_finish, triplanar_coverage, HatchMode, Hatching, LUMA};
use super::effects::rim::{rim_amount, Rim};
use super::effects::surface::SurfaceSettings;
use super::gpu_mesh::{MeshNormals, Placement as Stored};
use super::gpu_tests::{backends, open, view_lights};
use super::reference::{shade, RefLight};
use super::scene::camera::{Camera, Placement, Projection};
use super::scene::light::{Light, LightKind, Space};
use super::scene::material::Material;
use super::scene::{FrameSpec, Output, Scene, SceneItem, IDENTITY};

const SIZE: usize = 72;
/// The height field's amplitude: steep enough for a rim where it turns away from the view.
const AMPLITUDE: f64 = 0.3;

/// A height field over [0, 1]^2 with its exact unit normals.
fn height_field() -> (Vec<[f64; 3]>, Vec<[u32; 3]>, Vec<[f32; 3]>) {
    let (mut v, f) = crate::mesh::shapes::grid(24, 0.0, 0).unwrap();
    let tau = std::f64::consts::TAU;
    let mut normals = Vec::with_capacity(v.len());
    for p in &mut v {
        let (x, y) = (p[0], p[1]);
        p[2] = AMPLITUDE * (tau * x).sin() * (tau * y).sin();
        let zx = AMPLITUDE * tau * (tau * x).cos() * (tau * y).sin();
        let zy = AMPLITUDE * tau * (tau * x).sin() * (tau * y).cos();
        let n = glam::DVec3::new(-zx, -zy, 1.0).normalize();
        normals.push([n.x as f32, n.y as f32, n.z as f32]);
    }
    (v, f, normals)
}

/// Barycentric coordinates of `q` in the triangle `t` (2D corners), extended beyond it.
fn barycentric(t: [[f64; 2]; 3], q: [f64; 2]) -> [f64; 3] {
    let d = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
    let b1 = ((q[0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (q[1] - t[0][1])) / d;
    let b2 = ((t[1][0] - t[0][0]) * (q[1] - t[0][1]) - (q[0] - t[0][0]) * (t[1][1] - t[0][1])) / d;
    [1.0 - b1 - b2, b1, b2]
}

/// What a pixel's fragment holds: the object-space point, the interpolated normal and stripe
/// values.
#[derive(Clone, Copy)]
struct Sample {
    p: [f64; 3],
    n: [f64; 3],
    stripes: [f64; 4],
}

fn lerp<const N: usize>(b: [f64; 3], v: [[f64; N]; 3]) -> [f64; N] {
    std::array::from_fn(|k| b[0] * v[0][k] + b[1] * v[1][k] + b[2] * v[2][k])
}

fn sub<const N: usize>(a: [f64; N], b: [f64; N]) -> [f64; N] {
    std::array::from_fn(|k| a[k] - b[k])
}

/// The effects of one combination, by name.
fn combinations() -> Vec<(String, SurfaceSettings)> {
    let dithers = [
        ("no dither", None),
        // turned: the pattern's angle held by the reference too
        ("screen dither", Some(Dither { amount: 0.3, angle: 30.0, ..Dither::new(DitherPattern::Bayer4) })),
        (
            "surface dither",
            Some(Dither {
                space: DitherSpace::Object,
                amount: 0.3,
                scale: 2.0,
                ..Dither::new(DitherPattern::Bayer4)
            }),
        ),
    ];
    let hatchings = [
        ("no hatching", None),
        ("triplanar", Some(Hatching { mode: HatchMode::Triplanar, spacing: 5.0, ..Hatching::default() })),
        ("field", Some(Hatching { mode: HatchMode::Field, spacing: 5.0, ..Hatching::default() })),
    ];
    let rims = [("no rim", None), ("rim", Some(Rim { width: 0.7, ..Rim::default() }))];
    let mut all = Vec::new();
    for (d, dither) in dithers {
        for (h, hatching) in hatchings {
            for (r, rim) in rims {
                all.push((format!("{d}, {h}, {r}"), SurfaceSettings { dither, hatching, rim }));
            }
        }
    }
    all
}

#[test]
fn every_combination_of_effects_and_mesh_colour_matches_the_cpu_references_on_both_backends() {
    let (v, f, normals) = height_field();
    let stripes = hatch_stripes(&v, &f, crate::edges::DEFAULT_CREASE_ANGLE, crate::cancel::Cancel::never())
        .unwrap()
        .per_vertex(v.len(), &f);
    let tint = [153u8, 230, 76, 255];
    let linear_tint = super::albedo::texture::linear(tint);
    let albedos = [
        ("plain", None),
        (
            "vertex-coloured",
            Some(Albedo { colors: Some(Colors::Vertex(vec![linear_tint; v.len()])), ..Default::default() }),
        ),
        (
            "textured",
            Some(Albedo {
                uv: Some(v.iter().map(|p| [p[0] as f32, p[1] as f32]).collect()),
                texture: Some(Texture { width: 2, height: 2, texels: vec![tint; 4] }),
                ..Default::default()
            }),
        ),
    ];
    let lights = vec![
        Light::default(),
        Light {
            kind: LightKind::Point { position: [1.2, -0.3, 0.8] },
            space: Space::World,
            color: [0.6, 0.5, 0.35],
            intensity: 0.7,
            shadows: None,
        },
    ];
    let camera = Camera {
        placement: Placement::LookAt { eye: [0.5, 0.5, 3.0], target: [0.5, 0.5, 0.0], up: [0.0, 1.0, 0.0] },
        projection: Projection::Orthographic { height: 0.9 },
        near: None,
        far: None,
    };
    let frame =
        FrameSpec { width: SIZE as u32, height: SIZE as u32, band_antialias: false, ..Default::default() };
    let combos = combinations();
    for backend in backends() {
        let r = open(backend).unwrap();
        for (what, albedo) in &albedos {
            let surface = if albedo.is_some() {
                Vec3::from(std::array::from_fn(|k| linear_tint[k]))
            } else {
                Vec3::ONE
            };
            let id = r
                .add_mesh_with(&v, f.clone(), MeshNormals::Given(normals.clone()), albedo.clone())
                .unwrap()
                .0;
            // the anchored effects read the stored coordinates
            let placement = r.mesh(id).unwrap().gpu.placement;
            let mut plain: Option<Vec<u8>> = None;
            for (name, effects) in &combos {
                let material = Material::bands([1.0; 3], None, None, false)
                    .unwrap()
                    .with_effects(effects.clone())
                    .unwrap();
                let scene = Scene {
                    items: vec![SceneItem {
                        mesh: id,
                        transform: IDENTITY,
                        material: material.clone(),
                        splats: false,
                    }],
                    camera,
                    lights: lights.clone(),
                    ..Default::default()
                };
                let out = r.render(&scene, &frame).unwrap();
                let color = out.bytes(Output::Color).unwrap().to_vec();
                let view = DMat4::from_cols_array_2d(&out.report.view).transpose();
                let proj = DMat4::from_cols_array_2d(&out.report.proj).transpose();
                let inv = (proj * view).inverse();
                let ref_lights = view_lights(&scene, &view);
                let world = |x: f64, y: f64| {
                    let q =
                        inv * DVec4::new(x / SIZE as f64 * 2.0 - 1.0, 1.0 - y / SIZE as f64 * 2.0, 0.5, 1.0);
                    [q.x / q.w, q.y / q.w]
                };
                let (mut good, mut n) = (0usize, 0usize);
                for y in 0..SIZE {
                    for x in 0..SIZE {
                        let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                        let q = world(cx, cy);
                        let Some(tri) = f.iter().find(|t| {
                            let b = barycentric(t.map(|i| [v[i as usize][0], v[i as usize][1]]), q);
                            b.iter().all(|&b| b >= 1e-6)
                        }) else {
                            continue;
                        };
                        let corners = tri.map(|i| [v[i as usize][0], v[i as usize][1]]);
                        let at = |q: [f64; 2]| {
                            let b = barycentric(corners, q);
                            Sample {
                                p: lerp(b, tri.map(|i| v[i as usize])),
                                n: lerp(b, tri.map(|i| normals[i as usize].map(|c| c as f64))),
                                stripes: lerp(b, tri.map(|i| stripes[i as usize].map(|c| c as f64))),
                            }
                        };
                        let pixel = |x: usize, y: usize| at(world(x as f64 + 0.5, y as f64 + 0.5));
                        let want = reference_pixel(
                            &material,
                            &pixel,
                            [x, y],
                            &view,
                            &placement,
                            &ref_lights,
                            to_linear(scene.ambient),
                            surface,
                        );
                        let i = y * SIZE + x;
                        n += 1;
                        good +=
                            (0..3).all(|k| (color[4 * i + k] as i32 - want[k] as i32).abs() <= 2) as usize;
                    }
                }
                let ok = good as f64 / n.max(1) as f64;
                eprintln!("{backend:?}, {what}, {name}: {ok:.4} of {n} pixels match");
                assert!(n > SIZE * SIZE * 3 / 4, "{backend:?}, {what}, {name}: {n} pixels on the field");
                assert!(ok >= 0.97, "{backend:?}, {what}, {name}: only {ok:.4} of {n} pixels match");
                // each effect shows: the frame differs from the one without effects
                match &plain {
                    None => plain = Some(color),
                    Some(p) => {
                        let changed = p.chunks(4).zip(color.chunks(4)).filter(|(a, b)| a != b).count();
                        assert!(changed > 100, "{backend:?}, {what}, {name}: only {changed} pixels changed");
                    }
                }
            }
        }
    }
}

/// The sRGB colour of pixel `[x, y]`, `pixel` giving the fragment of its triangle at any pixel
/// (its plane extended, as at a helper pixel): the CPU references of each stage in the shader's
/// order.
#[allow(clippy::too_many_arguments)]
fn reference_pixel(
    m: &Material,
    pixel: &dyn Fn(usize, usize) -> Sample,
    [x, y]: [usize; 2],
    view: &DMat4,
    placement: &Stored,
    lights: &[RefLight],
    ambient: [f32; 3],
    albedo: Vec3,
) -> [u8; 3] {
    let e = &m.effects;
    let (s, sx, sy) = (pixel(x, y), pixel(x + 1, y), pixel(x, y + 1));
    let centre = [x as f64 + 0.5, y as f64 + 0.5];
    let p = view.transform_point3(s.p.into()).as_vec3();
    // the point where the anchored effects read it, and its change across the pixel
    let anchor = placement.to_stored(s.p);
    let [ax, ay] = [sx.p, sy.p].map(|q| sub(placement.to_stored(q), anchor));
    let n = view.transform_vector3(glam::DVec3::from(s.n).normalize()).as_vec3();
    let jitter = e.dither.map_or(0.0, |d| {
        let cell = match d.space {
            DitherSpace::Screen => d.turned(centre).map(|c| (c / d.scale).floor()),
            DitherSpace::Object => {
                // the octave whose cells are about `scale` pixels, on the plane the normal faces;
                // each pixel of the 2x2 quad picks its own plane, and the change across the pixel
                // is the quad's (fine derivatives)
                let plane = |q: [f64; 3], n: [f64; 3]| {
                    let a = n.map(f64::abs);
                    if a[0] >= a[1] && a[0] >= a[2] {
                        [q[1], q[2]]
                    } else if a[1] >= a[2] {
                        [q[2], q[0]]
                    } else {
                        [q[0], q[1]]
                    }
                };
                let q_at = |x: usize, y: usize| {
                    let s = pixel(x, y);
                    plane(placement.to_stored(s.p), s.n)
                };
                let q = q_at(x, y);
                let (x0, y0) = (x & !1, y & !1);
                let qx = sub(q_at(x0 + 1, y), q_at(x0, y));
                let qy = sub(q_at(x, y0 + 1), q_at(x, y0));
                let w = (qx[0].abs() + qy[0].abs()).max(qx[1].abs() + qy[1].abs());
                let k = (1.0 / (d.scale * w).max(1e-30)).log2().floor().exp2();
                d.turned(q).map(|c| (c * k).floor())
            }
        };
        let [cx, cy] = cell.map(|c| c as i32 as u32);
        ((d.pattern.threshold(cx, cy) - 0.5) * d.amount) as f32
    });
    let mut c = shade(m, n, p, true, Vec3::from(ambient), lights, [Vec3::ZERO; 2], albedo, jitter);
    if let Some(h) = &e.hatching {
        let layers = match h.mode {
            HatchMode::Triplanar => triplanar_coverage(anchor, s.n, ax, ay, h),
            HatchMode::Field => {
                let d = |a: [f64; 4], k: usize| [a[k] - s.stripes[k], a[k + 1] - s.stripes[k + 1]];
                let psi = [[s.stripes[0], s.stripes[1]], [s.stripes[2], s.stripes[3]]];
                field_coverage(
                    psi,
                    [d(sx.stripes, 0), d(sx.stripes, 2)],
                    [d(sy.stripes, 0), d(sy.stripes, 2)],
                    h,
                )
            }
        };
        let paper = Vec3::from(m.diffuse_linear()) * albedo;
        let luma = Vec3::from(LUMA.map(|c| c as f32));
        let tone = c.dot(luma) / paper.dot(luma).max(1e-6);
        let ink = to_linear(h.ink).map(|c| c as f64);
        let paper = [paper.x, paper.y, paper.z].map(|c| c as f64);
        c = Vec3::from(hatch_finish(paper, ink, tone as f64, layers).map(|c| c as f32));
    }
    if let Some(rim) = &e.rim {
        let nv = n.z;
        let lit = lights.iter().fold(-1.0f32, |best, l| best.max(n.dot(l.toward(p).0)));
        c = Vec3::from(rim.finish(c.into(), rim_amount(rim, nv, lit, 0.0, 0.0)));
    }
    let c = c.clamp(Vec3::ZERO, Vec3::ONE);
    [c.x, c.y, c.z].map(|v| linear_to_srgb8(v as f64))
}
