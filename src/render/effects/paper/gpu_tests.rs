//! The paper on the device (Vulkan and GL) against its CPU reference: every pixel of a frame
//! with paper is the reference applied to the same frame without it.

use super::{grain_at, Paper, PaperSpace};
use crate::render::color::{linear_to_srgb8, srgb_to_linear};
use crate::render::effects::outlines::settings::Outlines;
use crate::render::gpu_mesh::NormalMode;
use crate::render::gpu_tests::{all_outputs, backends, open, sphere_scene};
use crate::render::scene::material::Material;
use crate::render::scene::{FrameSpec, Output};
use crate::render::settings::GreyImage;

/// The share of pixels of `with` within 2 levels of `without` taken through the reference,
/// of those `reference` gives a grain for.
fn agreement(
    paper: &Paper,
    with: &[u8],
    without: &[u8],
    width: usize,
    grain: impl Fn(usize, usize) -> Option<f32>,
) -> (f64, usize) {
    let (mut good, mut n) = (0, 0);
    for (i, (a, b)) in with.chunks(4).zip(without.chunks(4)).enumerate() {
        let Some(g) = grain(i % width, i / width) else { continue };
        n += 1;
        let c = [0, 1, 2].map(|k| srgb_to_linear(b[k] as f64 / 255.0) as f32);
        let want = paper.color(c, g).map(|x| linear_to_srgb8(x as f64) as i32);
        good += (0..3).all(|k| (a[k] as i32 - want[k]).abs() <= 2) as usize;
    }
    (good as f64 / n.max(1) as f64, n)
}

#[test]
fn the_paper_matches_the_cpu_reference_on_the_screen_and_the_background_on_both_backends() {
    let image = GreyImage { width: 3, height: 2, values: vec![0.0, 0.5, 1.0, 0.25, 0.75, 0.1] };
    let papers = [
        Paper::default(),
        Paper { grain: Some(image), scale: 2.5, strength: 1.0, tone: 0.3, ..Paper::default() },
        Paper { space: PaperSpace::Surface, ..Paper::default() },
    ];
    for backend in backends() {
        let r = open(backend).unwrap();
        for (k, paper) in papers.iter().enumerate() {
            let mut scene = sphere_scene(&r, Material::default(), NormalMode::Smooth);
            scene.outlines = Some(Outlines::new(true, false));
            let frame = FrameSpec { outputs: all_outputs(97, 61).outputs, ..all_outputs(97, 61) };
            let without = r.render(&scene, &frame).unwrap();
            scene.effects.paper = Some(paper.clone());
            let with = r.render(&scene, &frame).unwrap();
            assert!(with.report.passes.contains(&"paper"), "{:?}", with.report.passes);
            let tile = super::tile(paper);
            let depth = without.floats(Output::Depth).unwrap();
            let screen = |x: usize, y: usize| {
                let surface = paper.space == PaperSpace::Surface && depth[y * 97 + x].is_finite();
                let s = paper.scale as f32;
                (!surface).then(|| grain_at(&tile, (x as f32 + 0.5) / s, (y as f32 + 0.5) / s))
            };
            let (a, b) = (with.bytes(Output::Color).unwrap(), without.bytes(Output::Color).unwrap());
            let (ok, n) = agreement(paper, a, b, 97, screen);
            eprintln!("{backend:?} paper {k}: {ok:.4} of {n} pixels match");
            assert!(n > 1000, "{backend:?} paper {k}: {n} pixels");
            assert!(ok >= 0.99, "{backend:?} paper {k}: only {ok} of {n} pixels match");
            // and on the surface the grain shows as on the screen: pixels change, within the
            // reference's range for the darkest and lightest grain
            if paper.space == PaperSpace::Surface {
                let on = |i: usize| depth[i].is_finite();
                let changed =
                    (0..97 * 61).filter(|&i| on(i) && a[4 * i..4 * i + 3] != b[4 * i..4 * i + 3]).count();
                let covered = (0..97 * 61).filter(|&i| on(i)).count();
                assert!(changed * 2 > covered, "{backend:?}: {changed} of {covered} surface pixels changed");
                for i in (0..97 * 61).filter(|&i| on(i)) {
                    let c = [0, 1, 2].map(|k| srgb_to_linear(b[4 * i + k] as f64 / 255.0) as f32);
                    let (lo, hi) = (paper.color(c, 0.0), paper.color(c, 1.0));
                    for k in 0..3 {
                        let range = linear_to_srgb8(lo[k].min(hi[k]) as f64)
                            ..=linear_to_srgb8(lo[k].max(hi[k]) as f64);
                        let got = a[4 * i + k];
                        assert!(
                            range.start().saturating_sub(2) <= got && got <= range.end().saturating_add(2),
                            "{backend:?}: pixel {i} channel {k}: {got} outside {range:?}"
                        );
                    }
                }
            }
        }
    }
}
