//! Eye-dome lighting on the device (Vulkan and GL) against its CPU twin: every pixel of a frame
//! with it is the frame without it times `EyeDome::shade_at` of the frame's depth, in linear
//! light.

use super::EyeDome;
use crate::render::color::{linear_to_srgb8, srgb_to_linear};
use crate::render::effects::outlines::settings::Outlines;
use crate::render::gpu_mesh::NormalMode;
use crate::render::gpu_tests::{all_outputs, backends, open, sphere_scene};
use crate::render::scene::material::Material;
use crate::render::scene::Output;

#[test]
fn eye_dome_lighting_matches_its_cpu_twin_on_both_backends() {
    let settings = [EyeDome::default(), EyeDome { strength: 0.3, radius: 3.0 }];
    for backend in backends() {
        let r = open(backend).unwrap();
        let mut scene = sphere_scene(&r, Material::default(), NormalMode::Flat);
        // a second sphere in front of the first: a depth step across the image
        let mut front = scene.items[0].clone();
        front.transform =
            [[0.5, 0.0, 0.0, 0.6], [0.0, 0.5, 0.0, -0.3], [0.0, 0.0, 0.5, 0.9], [0.0, 0.0, 0.0, 1.0]];
        scene.items.push(front);
        let (w, h) = (97usize, 61usize);
        let frame = all_outputs(w as u32, h as u32);
        let without = r.render(&scene, &frame).unwrap();
        assert!(!without.report.passes.contains(&"eye_dome"), "runs only when asked for");
        for (k, edl) in settings.iter().enumerate() {
            // with image-space outlines too: the geometry target then holds normals as well
            for outlines in [None, Some(Outlines::new(false, true))] {
                let mut scene = scene.clone();
                let inked = outlines.is_some();
                scene.outlines = outlines;
                let base = r.render(&scene, &frame).unwrap();
                scene.effects.eye_dome = Some(*edl);
                let with = r.render(&scene, &frame).unwrap();
                assert!(with.report.passes.contains(&"eye_dome"), "{:?}", with.report.passes);
                let depth = base.floats(Output::Depth).unwrap();
                let (a, b) = (with.bytes(Output::Color).unwrap(), base.bytes(Output::Color).unwrap());
                let (mut good, mut darker, mut n) = (0, 0, 0);
                for i in 0..w * h {
                    if inked && a[4 * i..4 * i + 3] == b[4 * i..4 * i + 3] && b[4 * i] < 40 {
                        continue; // the ink, drawn after
                    }
                    n += 1;
                    let shade = edl.shade_at(depth, w, h, i % w, i / w);
                    let want =
                        |c: u8| linear_to_srgb8(srgb_to_linear(c as f64 / 255.0) * shade as f64) as i32;
                    good += (0..3).all(|c| (a[4 * i + c] as i32 - want(b[4 * i + c])).abs() <= 2) as usize;
                    darker += (shade < 0.9) as usize;
                }
                let ok = good as f64 / n as f64;
                eprintln!("{backend:?} eye dome {k} (ink {inked}): {ok:.4} of {n}, {darker} darkened");
                assert!(ok >= 0.99, "{backend:?} eye dome {k}: only {ok} of {n} pixels match");
                assert!(darker > 20, "{backend:?} eye dome {k}: the step darkens only {darker} pixels");
            }
        }
    }
}

#[test]
fn offsets_ring_the_pixel() {
    let o = EyeDome { radius: 2.0, ..EyeDome::default() }.offsets();
    assert_eq!(o[0], [2, 0]);
    assert_eq!(o[2], [0, 2]);
    assert_eq!(o[1], [1, 1]);
    // a flat depth image is left as it is; a pixel behind its neighbours darkens
    let e = EyeDome::default();
    let flat = vec![2.0f32; 25];
    assert_eq!(e.shade_at(&flat, 5, 5, 2, 2), 1.0);
    let mut pit = flat.clone();
    pit[12] = 2.2;
    assert!(e.shade_at(&pit, 5, 5, 2, 2) < 0.01);
    assert_eq!(e.shade_at(&pit, 5, 5, 1, 2), 1.0);
    let mut hole = flat;
    hole[12] = f32::INFINITY;
    assert_eq!(e.shade_at(&hole, 5, 5, 2, 2), 1.0);
}
