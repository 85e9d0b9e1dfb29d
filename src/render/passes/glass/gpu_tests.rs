//! The glass stage on the device (Vulkan and GL), held against its CPU twin: three squares
//! seen head on, blue (opacity 0.5) over green (0.4) over opaque red, each square's shaded
//! colour measured by drawing it alone and opaque, the composite computed by `reference`.

use super::reference::{over, peeled, Fragment};
use crate::render::color::{linear_to_srgb8, to_linear};
use crate::render::gpu_mesh::NormalMode;
use crate::render::gpu_tests::{backends, open};
use crate::render::renderer::Renderer;
use crate::render::scene::camera::{Camera, Placement, Projection};
use crate::render::scene::material::Material;
use crate::render::scene::{FrameSpec, MeshId, Output, Scene, SceneItem, IDENTITY};

const SIZE: u32 = 64;

/// A square of half side `half` at height `z`, facing +z.
fn square(r: &Renderer, half: f64, z: f64) -> MeshId {
    let v = [[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]];
    r.add_mesh(&v, vec![[0, 1, 2], [0, 2, 3]], NormalMode::Flat).unwrap()
}

/// The squares (mesh, colour, opacity, height) seen from +z, orthographic, in that order.
fn scene(squares: &[(MeshId, [f64; 3], f32)]) -> Scene {
    let camera = Camera {
        placement: Placement::LookAt { eye: [0.0, 0.0, 5.0], target: [0.0; 3], up: [0.0, 1.0, 0.0] },
        projection: Projection::Orthographic { height: 2.0 },
        near: Some(1.0),
        far: Some(10.0),
    };
    let items = squares
        .iter()
        .map(|&(mesh, color, opacity)| {
            let material = Material { opacity, ..Material::lambert(color, None, false).unwrap() };
            SceneItem { mesh, transform: IDENTITY, material, splats: false }
        })
        .collect();
    Scene { items, camera, ..Default::default() }
}

fn linear(pixel: &[u8]) -> [f32; 3] {
    to_linear([pixel[0] as f64 / 255.0, pixel[1] as f64 / 255.0, pixel[2] as f64 / 255.0])
}

#[test]
fn peeled_glass_is_the_cpu_twin_in_any_order_on_both_backends() {
    let frame = FrameSpec { width: SIZE, height: SIZE, ..Default::default() };
    for backend in backends() {
        let r = open(backend).unwrap();
        // red covers the view; green the middle; blue a square across green's corner
        let (red, green, blue) = (square(&r, 2.0, 0.0), square(&r, 0.5, 0.5), square(&r, 0.4, 1.0));
        let colors: [[f64; 3]; 3] = [[0.9, 0.1, 0.1], [0.1, 0.8, 0.2], [0.1, 0.2, 0.9]];
        let alone = |mesh, color| {
            r.render(&scene(&[(mesh, color, 1.0)]), &frame).unwrap().bytes(Output::Color).unwrap().to_vec()
        };
        let (c_red, c_green, c_blue) =
            (alone(red, colors[0]), alone(green, colors[1]), alone(blue, colors[2]));
        let white = [255u8, 255, 255];
        let glass = [(red, colors[0], 1.0), (green, colors[1], 0.4), (blue, colors[2], 0.5)];
        let mut images = Vec::new();
        for order in [[0, 1, 2], [2, 1, 0], [1, 2, 0]] {
            let out = r.render(&scene(&order.map(|i| glass[i])), &frame).unwrap();
            assert_eq!(
                out.report.passes.iter().filter(|p| **p == "glass_peel").count(),
                frame.glass_layers as usize
            );
            images.push(out.bytes(Output::Color).unwrap().to_vec());
        }
        let (mut worst, mut layered) = (0i32, 0);
        for p in 0..(SIZE * SIZE) as usize {
            let at = |c: &[u8]| c[4 * p..4 * p + 3].to_vec();
            let covered = |c: &[u8]| at(c) != white;
            let mut frags = Vec::new();
            for (img, depth, opacity) in [(&c_green, 4.5, 0.4), (&c_blue, 4.0, 0.5)] {
                if covered(img) {
                    frags.push(Fragment { depth, color: linear(&at(img)), opacity });
                }
            }
            layered += (frags.len() == 2) as usize;
            let want = peeled(&frags, 5.0, linear(&at(&c_red)), frame.glass_layers);
            let exact = over(&frags, 5.0, linear(&at(&c_red)));
            assert!(want.iter().zip(exact).all(|(a, b)| (a - b).abs() < 1e-6), "4 layers peel 2 exactly");
            let want = want.map(|c| linear_to_srgb8(c as f64));
            for img in &images {
                for (g, w) in at(img).iter().zip(want) {
                    worst = worst.max((*g as i32 - w as i32).abs());
                }
            }
            // the orders agree within a level
            for img in &images[1..] {
                assert!(at(img).iter().zip(at(&images[0])).all(|(a, b)| (*a as i32 - b as i32).abs() <= 1));
            }
        }
        assert!(layered > 100, "{backend:?}: {layered} pixels behind two glass squares");
        assert!(worst <= 2, "{backend:?}: {worst} levels from the CPU twin");
    }
}
