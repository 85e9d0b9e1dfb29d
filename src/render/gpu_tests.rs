//! Renders on the real device (Vulkan and GL; Mesa's software drivers where there is no GPU)
//! and holds the pixels against `reference.rs`.

use glam::{DMat4, DVec3, DVec4, Vec3};

use super::color::{linear_to_srgb8, to_linear};
use super::device::BackendChoice;
use super::effects::outlines::settings::Outlines;
use super::gpu_mesh::NormalMode;
use super::reference::{shade, RefLight};
use super::renderer::{RenderOutput, Renderer};
use super::scene::camera::{Camera, Placement, Projection};
use super::scene::light::{Light, ViewLight};
use super::scene::material::Material;
use super::scene::model::{kang_table, Highlight, Model};
use super::scene::{FrameSpec, Output, Outputs, Scene, SceneItem, IDENTITY};
use crate::mesh::shapes::icosphere;

/// Opens a renderer as the package does: with a private runtime directory where the environment
/// has none, so that Mesa's Wayland probe does not print "XDG_RUNTIME_DIR is invalid" into the
/// test log (the Python package does the same at import, in `_runtime_dir.py`).
pub(super) fn open(backend: BackendChoice) -> crate::error::Result<Renderer> {
    static RUNTIME_DIR: std::sync::Once = std::sync::Once::new();
    RUNTIME_DIR.call_once(|| {
        let usable = std::env::var_os("XDG_RUNTIME_DIR")
            .map(std::path::PathBuf::from)
            .is_some_and(|p| p.is_absolute() && p.is_dir());
        if !usable {
            // One fixed directory, reused by every test run, so that runs leave nothing behind.
            let dir = std::env::temp_dir().join("toonmesh-test-runtime");
            if std::fs::create_dir_all(&dir).is_ok() {
                use std::os::unix::fs::PermissionsExt;
                let _ = std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700));
                // Set before any device opens (tests that open one come through here first).
                std::env::set_var("XDG_RUNTIME_DIR", &dir);
            }
        }
    });
    Renderer::new(backend)
}

/// Asserts that a coverage image is its CPU reference `want` but for rounding and
/// antialiasing: a mean absolute difference under 0.01, and under 0.5% of pixels off by more
/// than 0.25. `case` names the run in a failure.
fn assert_coverage_close(got: &[f32], want: &[f32], case: &str) {
    let n = got.len() as f64;
    let mean = got.iter().zip(want).map(|(a, b)| (a - b).abs() as f64).sum::<f64>() / n;
    let off = got.iter().zip(want).filter(|(a, b)| (*a - *b).abs() > 0.25).count() as f64 / n;
    assert!(mean < 0.01 && off < 0.005, "{case}: mean difference {mean}, {off} of pixels off by > 0.25");
}

/// A sphere lit by the key light and a warm point light, seen from the front, a little from the
/// right and above (where the shadowed side's crescent shows: the rim's test needs it).
pub(super) fn sphere_scene(r: &Renderer, material: Material, normals: NormalMode) -> Scene {
    let (v, f) = icosphere(4, 0.0, 0).unwrap();
    let id = r.add_mesh(&v, f, normals).unwrap();
    let placement = Placement::Fit { direction: Some([0.35, 0.3, 1.0]), up: None, margin: 1.05, turn: 0.0 };
    Scene {
        items: vec![SceneItem { mesh: id, transform: IDENTITY, material, splats: false }],
        camera: Camera { placement, ..Camera::default() },
        lights: vec![
            Light::default(),
            Light {
                kind: super::scene::light::LightKind::Point { position: [3.0, 1.0, 2.0] },
                space: super::scene::light::Space::World,
                color: [0.6, 0.5, 0.35],
                intensity: 0.5,
                shadows: None,
            },
        ],
        ..Default::default()
    }
}

pub(super) fn all_outputs(w: u32, h: u32) -> FrameSpec {
    FrameSpec {
        width: w,
        height: h,
        outputs: Outputs::of(&[Output::Color, Output::Normal, Output::Depth]),
        ..Default::default()
    }
}

/// Fraction of covered pixels whose colour matches the reference from the normal and depth outputs.
fn agreement(scene: &Scene, out: &RenderOutput) -> (f64, usize) {
    agreement_of(scene, out, false)
}

/// `agreement`, with band borders blended over the normal's change across each pixel when
/// `blended` (pixels whose 2x2 quad is not all surface are left out: the shader's derivatives
/// there come from helper pixels the read-back does not hold).
fn agreement_of(scene: &Scene, out: &RenderOutput, blended: bool) -> (f64, usize) {
    agreement_with(scene, out, blended, |c, _| c)
}

/// A covered pixel as a per-pixel effect's reference sees it: the view's lights, and the
/// surface's unit normal and view-space point at any pixel (None off the surface), for the
/// derivatives the shader takes over the pixel's 2x2 quad.
pub(super) struct RefPixel<'a> {
    pub x: usize,
    pub y: usize,
    pub orthographic: bool,
    pub lights: &'a [RefLight],
    pub surface: &'a dyn Fn(usize, usize) -> Option<(Vec3, Vec3)>,
}

/// `agreement_of`, the reference's colour changed by `finish` (a per-pixel effect's CPU twin;
/// linear colour in and out) before it is compared.
pub(super) fn agreement_with(
    scene: &Scene,
    out: &RenderOutput,
    blended: bool,
    finish: impl Fn(Vec3, &RefPixel<'_>) -> Vec3,
) -> (f64, usize) {
    let (w, h) = (out.width as usize, out.height as usize);
    let proj = DMat4::from_cols_array_2d(&out.report.proj).transpose();
    let view = DMat4::from_cols_array_2d(&out.report.view).transpose();
    let lights = view_lights(scene, &view);
    let (color, normal, depth) = (
        out.bytes(Output::Color).unwrap(),
        out.floats(Output::Normal).unwrap(),
        out.floats(Output::Depth).unwrap(),
    );
    let inv = proj.inverse();
    let orthographic = proj.w_axis.w == 1.0;
    let surface = |x: usize, y: usize| -> Option<(Vec3, Vec3)> {
        let j = y * w + x;
        let z = *depth.get(j).filter(|z| x < w && y < h && z.is_finite())?;
        let n = Vec3::new(normal[3 * j], normal[3 * j + 1], normal[3 * j + 2]);
        // the view-space point on the pixel's ray at linear depth z
        let ndc =
            DVec3::new((x as f64 + 0.5) / w as f64 * 2.0 - 1.0, 1.0 - (y as f64 + 0.5) / h as f64 * 2.0, 0.5);
        let q = inv * DVec4::new(ndc.x, ndc.y, ndc.z, 1.0);
        let q = q.truncate() / q.w;
        let p = if orthographic { DVec3::new(q.x, q.y, -(z as f64)) } else { q * (z as f64 / -q.z) };
        Some((n, p.as_vec3()))
    };
    let (mut good, mut covered) = (0usize, 0usize);
    for y in 0..h {
        for x in 0..w {
            let Some((n, p)) = surface(x, y) else { continue };
            let dn = if blended {
                match super::reference::quad_derivatives(|x, y| surface(x, y).map(|s| s.0), x, y) {
                    Some(d) => d,
                    None => continue,
                }
            } else {
                [Vec3::ZERO; 2]
            };
            covered += 1;
            let c = shade(
                &scene.items[0].material,
                n,
                p,
                orthographic,
                Vec3::from(to_linear(scene.ambient)),
                &lights,
                dn,
                Vec3::ONE,
                0.0,
            );
            let c = finish(c, &RefPixel { x, y, orthographic, lights: &lights, surface: &surface });
            let want = [c.x, c.y, c.z].map(|v| linear_to_srgb8(v as f64) as i32);
            let i = y * w + x;
            if (0..3).all(|k| (color[4 * i + k] as i32 - want[k]).abs() <= 1) {
                good += 1;
            }
        }
    }
    (good as f64 / covered.max(1) as f64, covered)
}

/// The scene's lights as the shader receives them, in the view space of `view`.
pub(super) fn view_lights(scene: &Scene, view: &DMat4) -> Vec<RefLight> {
    let light = |l: &Light| match l.to_view(view) {
        ViewLight::Toward(d) => RefLight::Toward(d.as_vec3(), Vec3::from(l.radiance())),
        ViewLight::At(p) => RefLight::At(p.as_vec3(), Vec3::from(l.radiance())),
    };
    scene.lights.iter().map(light).collect()
}

pub(super) fn backends() -> Vec<BackendChoice> {
    vec![BackendChoice::Vulkan, BackendChoice::Gl]
}

#[test]
fn band_borders_blended_over_a_pixel_match_the_cpu_reference_on_both_backends() {
    let models = [
        Model::ThresholdedPhong { t_h: 0.1, t_s: 0.95, highlight: Highlight::Blinn },
        Model::Bands { thresholds: vec![0.2, 0.5, 0.7, 0.9], values: vec![0.0, 0.2, 0.7, 0.9, 1.0] },
        Model::Lut { table: kang_table() },
    ];
    for backend in backends() {
        let r = open(backend).unwrap();
        for model in &models {
            let material = Material { model: model.clone(), ..Material::default() };
            let scene = sphere_scene(&r, material, NormalMode::Smooth);
            let frame = all_outputs(161, 97);
            assert!(frame.band_antialias, "blended by default");
            let out = r.render(&scene, &frame).unwrap();
            let (ok, covered) = agreement_of(&scene, &out, true);
            assert!(covered > 3000, "{backend:?} model {}: {covered} pixels", model.id());
            // the shader's derivatives extend each triangle's interpolation over its 2x2 quad; the
            // reference differences the neighbours' normals, from the next triangle across an
            // edge: a border pixel there may blend a little differently
            assert!(ok >= 0.98, "{backend:?} model {}: only {ok} of covered pixels match", model.id());
            // and the borders are blended: tones between the bands show
            let hard = r.render(&scene, &FrameSpec { band_antialias: false, ..frame }).unwrap();
            let distinct = |o: &RenderOutput| {
                let mut c: Vec<[u8; 3]> =
                    o.bytes(Output::Color).unwrap().chunks(4).map(|p| [p[0], p[1], p[2]]).collect();
                c.sort_unstable();
                c.dedup();
                c.len()
            };
            assert!(distinct(&out) > 2 * distinct(&hard), "{backend:?} model {}", model.id());
        }
    }
}

#[test]
fn every_model_matches_the_cpu_reference_on_both_backends() {
    let models = [
        Model::Lambert,
        Model::Phong { shininess: 20.0 },
        Model::ThresholdedPhong { t_h: 0.1, t_s: 0.95, highlight: Highlight::Blinn },
        Model::Bands { thresholds: vec![0.2, 0.5, 0.7, 0.9], values: vec![0.0, 0.2, 0.7, 0.9, 1.0] },
        Model::Lut { table: kang_table() },
    ];
    for backend in backends() {
        let r = open(backend).expect("a GPU adapter (install Mesa's lavapipe/llvmpipe)");
        for model in &models {
            let material = Material {
                model: model.clone(),
                ambient: [0.2, 0.2, 0.3],
                diffuse: [0.8, 0.5, 0.3],
                specular: [0.5, 0.5, 0.5],
                per_vertex: false,
                effects: Default::default(),
                opacity: 1.0,
            };
            let scene = sphere_scene(&r, material, NormalMode::Smooth);
            let hard = FrameSpec { band_antialias: false, ..all_outputs(161, 97) };
            let out = r.render(&scene, &hard).unwrap();
            let (ok, covered) = agreement(&scene, &out);
            assert!(covered > 3000, "{backend:?} model {}: the sphere covers {covered} pixels", model.id());
            // band and threshold edges: a pixel whose L.n lies within f16-free f32 rounding of a
            // threshold may land on either side; they are far fewer than 0.5%
            assert!(ok >= 0.995, "{backend:?} model {}: only {ok} of covered pixels match", model.id());
        }
    }
}

#[test]
fn odd_and_tiny_sizes_read_back_whole_rows() {
    for backend in backends() {
        let r = open(backend).unwrap();
        let scene = sphere_scene(&r, Material::default(), NormalMode::Flat);
        for (w, h) in [(301, 199), (1, 1), (3, 2)] {
            let out = r.render(&scene, &all_outputs(w, h)).unwrap();
            assert_eq!(out.bytes(Output::Color).unwrap().len(), (w * h * 4) as usize);
            assert_eq!(out.floats(Output::Normal).unwrap().len(), (w * h * 3) as usize);
            assert_eq!(out.floats(Output::Depth).unwrap().len(), (w * h) as usize);
        }
    }
}

#[test]
fn empty_scene_is_background() {
    let r = open(BackendChoice::Auto).unwrap();
    let scene = Scene { lights: vec![], ambient: [0.0; 3], ..Default::default() };
    let frame = FrameSpec { background: [0.2, 0.4, 0.6, 1.0], ..all_outputs(5, 4) };
    let out = r.render(&scene, &frame).unwrap();
    let c = out.bytes(Output::Color).unwrap();
    assert_eq!(&c[..4], &[51, 102, 153, 255]);
    assert!(out.floats(Output::Depth).unwrap().iter().all(|d| *d == f32::INFINITY));
    assert!(out.floats(Output::Normal).unwrap().iter().all(|n| *n == 0.0));
    let _ = Camera {
        placement: Placement::LookAt { eye: [0.0; 3], target: [0.0, 0.0, -1.0], up: [0.0, 1.0, 0.0] },
        projection: Projection::Perspective { fov_y_deg: 40.0 },
        near: None,
        far: None,
    };
}

/// A bumpy sphere and a smaller one in front of it, so that some lines are hidden.
fn two_spheres(r: &Renderer, outlines: Outlines) -> Scene {
    let (v, f) = icosphere(3, 0.04, 3).unwrap();
    let id = r.add_mesh(&v, f, NormalMode::Smooth).unwrap();
    let front = [[0.5, 0.0, 0.0, 0.4], [0.0, 0.5, 0.0, 0.2], [0.0, 0.0, 0.5, 1.2], [0.0, 0.0, 0.0, 1.0]];
    Scene {
        items: vec![
            SceneItem { mesh: id, transform: IDENTITY, material: Material::default(), splats: false },
            SceneItem { mesh: id, transform: front, material: Material::default(), splats: false },
        ],
        camera: Camera {
            placement: Placement::LookAt { eye: [0.3, 0.4, 5.0], target: [0.0; 3], up: [0.0, 1.0, 0.0] },
            projection: Projection::Perspective { fov_y_deg: 40.0 },
            near: None,
            far: None,
        },
        outlines: Some(outlines),
        ..Default::default()
    }
}

/// The screen lines a frame of `scene` draws, as the `silhouettes` step finds them, projected
/// as the lines pass projects them, and the camera of the frame.
fn screen_lines(
    r: &Renderer,
    scene: &Scene,
    frame: &FrameSpec,
) -> (Vec<super::effects::outlines::projection::ScreenLine>, super::scene::camera::ResolvedCamera) {
    use super::effects::outlines::mesh_lines::{
        chains, instances, reference_depth, scene_outlines, set_chains,
    };
    use super::effects::outlines::occluded::cut;
    use super::effects::outlines::projection::Projector;
    use super::effects::outlines::settings::VisibilityRule;
    let checked = r.check(scene.clone(), *frame).unwrap();
    let mut report = Default::default();
    let p = r.prepare(checked, &mut report).unwrap();
    let outlines = scene.outlines.as_ref().unwrap();
    let mut lines = Vec::new();
    let reference = reference_depth(&scene.items, &p.records, &p.cam);
    let outlines_of = scene_outlines(&scene.items, &p.records, &p.cam, outlines, None).unwrap();
    let projectors: Vec<Projector> = scene
        .items
        .iter()
        .zip(&p.records)
        .map(|(item, rec)| Projector::of(item, &rec.gpu.placement, &p.cam, frame.width, frame.height))
        .collect();
    let mut found: Vec<_> =
        outlines_of.iter().zip(&p.records).map(|(o, rec)| chains(o, &rec.host.positions)).collect();
    // the `Lines` items after the meshes, in view coordinates (their ink resolved by the check)
    let checked = r.check(scene.clone(), *frame).unwrap();
    found.extend(set_chains(&checked.scene.lines, &p.cam));
    let projectors: Vec<Projector> = projectors
        .into_iter()
        .chain(scene.lines.iter().map(|_| Projector::in_view(&p.cam, frame.width, frame.height)))
        .collect();
    if outlines.visibility == VisibilityRule::Exact {
        found = cut(found, (&p.records, &p.scene.glass), &projectors, p.cam.orthographic, outlines).unwrap();
    }
    for (projector, of_item) in projectors.iter().zip(&found) {
        let drawn = instances(of_item, projector, &outlines.stroke_width, reference);
        lines.extend(drawn.iter().filter_map(|l| l.screen(projector)));
    }
    (lines, p.cam)
}

/// A 240 x 180 frame of `scene` (drawn with `outlines`) against the CPU reference: the lines it
/// draws as the reference sees them, the frame's outline coverage, and the reference's coverage
/// of any of those lines under the frame's depth and a rule (`offset`: its depth offset, None:
/// the outlines').
struct LinesFrame {
    lines: Vec<super::effects::outlines::projection::ScreenLine>,
    outline: Vec<f32>,
    depth: Vec<f32>,
    cam: super::scene::camera::ResolvedCamera,
    outlines: Outlines,
}

impl LinesFrame {
    fn of(r: &Renderer, scene: &Scene) -> Self {
        let frame = FrameSpec {
            width: 240,
            height: 180,
            outputs: Outputs::of(&[Output::Outline, Output::Depth]),
            ..Default::default()
        };
        let out = r.render(scene, &frame).unwrap();
        let (lines, cam) = screen_lines(r, scene, &frame);
        let depth = out.floats(Output::Depth).unwrap().iter().map(|d| d / cam.scale as f32).collect();
        let outline = out.floats(Output::Outline).unwrap().to_vec();
        LinesFrame { lines, outline, depth, cam, outlines: scene.outlines.clone().unwrap() }
    }

    fn coverage(
        &self,
        lines: &[super::effects::outlines::projection::ScreenLine],
        offset: Option<f32>,
    ) -> Vec<f32> {
        use super::effects::outlines::settings::INK_KINDS;
        use super::effects::outlines::visibility::{coverage_image, DepthImage, Visibility};
        let o = &self.outlines;
        let img = DepthImage { depth: &self.depth, width: 240, height: 180 };
        let rule = Visibility::of(offset.unwrap_or(o.depth_offset), &self.cam, 180);
        let widths: Vec<f32> = (0..INK_KINDS).map(|k| o.styles[k].map_or(0.0, |s| s.width)).collect();
        let dashes: Vec<f32> = (0..INK_KINDS).map(|k| o.styles[k].map_or(0.0, |s| s.dash)).collect();
        coverage_image(lines, (&widths, &dashes), false, &img, rule)
    }
}

fn inked(coverage: &[f32]) -> usize {
    coverage.iter().filter(|&&c| c > 0.0).count()
}

#[test]
fn mesh_lines_match_the_cpu_visibility_reference_on_both_backends() {
    use super::effects::outlines::settings::{ContourRule, LineStyle, VisibilityRule, HIDDEN_KIND};
    use super::effects::outlines::stroke_width::StrokeWidth;
    let faces = Outlines {
        crease_angle: 25.0,
        contours: ContourRule::Faces,
        visibility: VisibilityRule::Depth,
        ..Outlines::new(true, false)
    };
    // smooth contours: lines through the faces, drawn by the same pass
    let smooth = Outlines { contours: ContourRule::Smooth, ..faces.clone() };
    // strokes tapered at their ends and wider where nearer
    let shaped = Outlines { stroke_width: StrokeWidth { taper: 40.0, by_depth: true }, ..faces.clone() };
    // the exact rule (lines cut on the host, drawn without the depth test), with hidden lines
    // dashed
    let mut exact = Outlines { visibility: VisibilityRule::Exact, ..smooth.clone() };
    exact.styles[HIDDEN_KIND] = Some(LineStyle::hidden(LineStyle::default()));
    let all = [faces, smooth, shaped, exact];
    for (backend, outlines) in backends().into_iter().flat_map(|b| all.clone().map(|o| (b, o))) {
        let r = open(backend).unwrap();
        let f = LinesFrame::of(&r, &two_spheres(&r, outlines.clone()));
        let want = f.coverage(&f.lines, None);
        let shown = inked(&want);
        assert!(shown > 500, "{backend:?}: the reference inks {shown} pixels");
        assert_coverage_close(&f.outline, &want, &format!("{backend:?}"));
        if outlines.visibility == VisibilityRule::Exact {
            // hidden lines drawn, dashed: some partly inked pixels along them
            let hidden: Vec<_> = f.lines.iter().filter(|l| l.kind == HIDDEN_KIND).copied().collect();
            assert!(
                hidden.len() > 20 && hidden.iter().all(|l| l.exact),
                "{backend:?}: {} hidden",
                hidden.len()
            );
            continue;
        }
        // the rule hides something here: with an infinite offset every line would show
        let all = inked(&f.coverage(&f.lines, Some(1e30)));
        assert!(all > shown + 200, "{backend:?}: hidden-line removal hid only {} pixels", all - shown);
    }
}

#[test]
fn lines_items_match_the_cpu_visibility_reference_on_both_backends() {
    use super::effects::outlines::settings::{LineStyle, VisibilityRule, HIDDEN_KIND};
    use super::scene::lines::LineSet;
    // a wire through the small sphere in front of the large one, and a bent one beside them
    let wire = LineSet {
        positions: vec![
            [-1.5, 0.2, 1.1],
            [1.5, 0.25, 1.1],
            [0.4, -1.4, 0.0],
            [1.4, -1.2, 0.5],
            [1.6, 0.8, 0.5],
        ],
        segments: vec![[0, 1], [2, 3], [3, 4]],
        transform: IDENTITY,
        color: Some([1.0, 0.0, 0.0]),
        width: Some(3.0),
    };
    let depth = Outlines { visibility: VisibilityRule::Depth, ..Outlines::new(true, false) };
    let mut exact = Outlines::new(true, false);
    exact.styles[HIDDEN_KIND] = Some(LineStyle::hidden(LineStyle::default()));
    for (backend, outlines) in backends().into_iter().flat_map(|b| [(b, depth.clone()), (b, exact.clone())]) {
        let r = open(backend).unwrap();
        let f = LinesFrame::of(&r, &Scene { lines: vec![wire.clone()], ..two_spheres(&r, outlines.clone()) });
        let own: Vec<_> = f.lines.iter().filter(|l| l.own_width == Some(3.0)).copied().collect();
        assert!(own.len() >= 3, "{backend:?}: {} of the wire's lines", own.len());
        assert_coverage_close(&f.outline, &f.coverage(&f.lines, None), &format!("{backend:?}"));
        // the small sphere hides part of the wire
        let (drawn, unhidden) = (inked(&f.coverage(&own, None)), inked(&f.coverage(&own, Some(1e30))));
        if outlines.visibility == VisibilityRule::Exact {
            // cut on the host: the hidden piece is drawn as a hidden line, in the hidden ink
            assert!(own.iter().all(|l| l.exact), "{backend:?}");
            assert!(f.lines.iter().any(|l| l.kind == HIDDEN_KIND && l.own_width.is_none()), "{backend:?}");
            assert!(drawn > 300, "{backend:?}: {drawn}");
        } else {
            assert!(unhidden > drawn + 20, "{backend:?}: the depth test hid nothing");
        }
    }
}

#[test]
fn image_edges_match_the_cpu_rule_on_the_same_buffers_on_both_backends() {
    use super::effects::outlines::edges_reference::edge_mask;
    use super::effects::outlines::settings::ImageRule;
    let outlines =
        Outlines { depth_threshold: 0.05, image_rule: ImageRule::Paper, ..Outlines::new(false, true) };
    for backend in backends() {
        let r = open(backend).unwrap();
        let scene = two_spheres(&r, outlines.clone());
        let frame = FrameSpec {
            width: 199,
            height: 151,
            outputs: Outputs::of(&[Output::Outline, Output::Normal, Output::Depth, Output::Color]),
            ..Default::default()
        };
        let out = r.render(&scene, &frame).unwrap();
        let (normal, depth) = (out.floats(Output::Normal).unwrap(), out.floats(Output::Depth).unwrap());
        let want = edge_mask(normal, depth, 151, 199, (outlines.normal_threshold, outlines.depth_threshold))
            .unwrap();
        let got: Vec<bool> = out.floats(Output::Outline).unwrap().iter().map(|&c| c > 0.5).collect();
        let agree = got.iter().zip(&want).filter(|(a, b)| a == b).count() as f64 / got.len() as f64;
        let edges = want.iter().filter(|&&e| e).count();
        assert!(edges > 300, "{backend:?}: {edges} edge pixels");
        assert!(agree >= 0.999, "{backend:?}: the GPU mask agrees on {agree} of pixels");
        // edge pixels are painted in the image ink (black) over the colour
        let color = out.bytes(Output::Color).unwrap();
        assert!(want.iter().zip(color.chunks(4)).filter(|(e, _)| **e).all(|(_, c)| c[..3] == [0, 0, 0]));
    }
}

#[test]
fn image_lines_match_the_cpu_discontinuity_rule_on_both_backends() {
    use super::effects::outlines::edges_reference::{Buffers, Discontinuity};
    use super::effects::outlines::settings::IMAGE_KIND;
    use super::uniforms::footprint;
    for (width, flat) in [(1.5f32, false), (4.0, true)] {
        let mut outlines = Outlines::new(false, true);
        outlines.styles[IMAGE_KIND] =
            Some(super::effects::outlines::settings::LineStyle { color: [0.0; 3], width, dash: 0.0 });
        for backend in backends() {
            let r = open(backend).unwrap();
            let mut scene = two_spheres(&r, outlines.clone());
            if flat {
                // faceted: normal turns between pixels on every face edge
                let (v, f) = icosphere(1, 0.0, 0).unwrap();
                scene.items[0].mesh = r.add_mesh(&v, f, NormalMode::Flat).unwrap();
            }
            let frame = FrameSpec {
                width: 181,
                height: 137,
                outputs: Outputs::of(&[Output::Outline, Output::Normal, Output::Depth]),
                ..Default::default()
            };
            let out = r.render(&scene, &frame).unwrap();
            let (_, cam) = screen_lines(&r, &scene, &frame);
            let (a, b) = footprint(&cam, frame.height);
            let rule = Discontinuity {
                normal_cos: (outlines.normal_angle as f64).to_radians().cos() as f32,
                depth_jump: outlines.depth_jump,
                // the read-back depth is in world units
                footprint: [a as f32, (b * cam.scale) as f32],
                orthographic: cam.orthographic,
                width,
            };
            let buf = Buffers {
                normal: out.floats(Output::Normal).unwrap(),
                depth: out.floats(Output::Depth).unwrap(),
                width: 181,
                height: 137,
            };
            let want = rule.coverage_image(&buf);
            let inked = want.iter().filter(|&&c| c > 0.5).count();
            assert!(inked > 300, "{backend:?}: the reference inks {inked} pixels");
            let got = out.floats(Output::Outline).unwrap();
            assert_coverage_close(got, &want, &format!("{backend:?} width {width}"));
        }
    }
}
