//! The rim on the device (Vulkan and GL) against its CPU reference.

use glam::Vec3;

use super::{rim_amount, Rim, RimBlend, RimSide};
use crate::render::effects::surface::SurfaceSettings;
use crate::render::gpu_mesh::NormalMode;
use crate::render::gpu_tests::{agreement_with, all_outputs, backends, open, sphere_scene, RefPixel};
use crate::render::reference::{quad_derivatives, view_dir};
use crate::render::scene::material::Material;
use crate::render::scene::model::Model;
use crate::render::scene::{FrameSpec, Output};

/// n.v and the largest n.l of a pixel.
fn terms(px: &RefPixel<'_>, x: usize, y: usize) -> Option<(f32, f32)> {
    let (n, p) = (px.surface)(x, y)?;
    let lit = px.lights.iter().fold(-1.0f32, |m, l| m.max(n.dot(l.toward(p).0)));
    Some((n.dot(view_dir(p, px.orthographic)), lit))
}

fn reference(rim: &Rim, blended: bool) -> impl Fn(Vec3, &RefPixel<'_>) -> Vec3 + '_ {
    move |c, px| {
        let (nv, lit) = terms(px, px.x, px.y).expect("a covered pixel");
        let (aa_nv, aa_lit) = if blended {
            let d = quad_derivatives(|x, y| terms(px, x, y).map(|t| glam::Vec2::new(t.0, t.1)), px.x, px.y)
                .expect("a whole quad");
            (glam::Vec2::new(d[0].x, d[1].x).length(), glam::Vec2::new(d[0].y, d[1].y).length())
        } else {
            (0.0, 0.0)
        };
        Vec3::from(rim.finish(c.into(), rim_amount(rim, nv, lit, aa_nv, aa_lit)))
    }
}

#[test]
fn the_rim_matches_the_cpu_reference_in_every_model_side_and_blend_on_both_backends() {
    let rims = [
        Rim::default(),
        Rim {
            side: RimSide::Lit,
            blend: RimBlend::Mix,
            color: [0.2, 0.4, 1.0],
            width: 0.45,
            ..Rim::default()
        },
        Rim { side: RimSide::Shadowed, softness: 0.2, strength: 1.0, ..Rim::default() },
    ];
    let models = [
        Model::Lambert,
        Model::Bands { thresholds: vec![0.2, 0.5], values: vec![0.1, 0.5, 1.0] },
        Model::Phong { shininess: 20.0 },
    ];
    for backend in backends() {
        let r = open(backend).unwrap();
        for (k, rim) in rims.iter().enumerate() {
            for (model, blended) in models.iter().zip([false, true, false]) {
                let effects = SurfaceSettings { rim: Some(*rim), ..Default::default() };
                let material = Material { model: model.clone(), effects, ..Material::default() };
                let scene = sphere_scene(&r, material.clone(), NormalMode::Smooth);
                let frame = FrameSpec { band_antialias: blended, ..all_outputs(161, 97) };
                let out = r.render(&scene, &frame).unwrap();
                let (ok, covered) = agreement_with(&scene, &out, blended, reference(rim, blended));
                assert!(covered > 3000, "{backend:?} rim {k} model {}: {covered} pixels", model.id());
                // blended borders (the bands' and the rim's) take their width from the quad's
                // neighbours, which the reference reads back across triangle edges: a pixel on a
                // border may blend a little differently (as in the bands' own test)
                let least = if blended { 0.96 } else { 0.98 };
                eprintln!("{backend:?} rim {k} model {}: {ok:.4} of {covered} pixels match", model.id());
                assert!(ok >= least, "{backend:?} rim {k} model {}: only {ok} of pixels match", model.id());
                // and the rim shows: without it, a band of pixels along the silhouette differs
                let plain = Material { effects: SurfaceSettings::default(), ..material };
                let without = r.render(&sphere_scene(&r, plain, NormalMode::Smooth), &frame).unwrap();
                let (a, b) = (out.bytes(Output::Color).unwrap(), without.bytes(Output::Color).unwrap());
                let changed = a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| p != q).count();
                // (the shadowed side's rim only where neither light reaches: a thin crescent)
                let least = if rim.side == RimSide::Shadowed { 10 } else { 200 };
                assert!(
                    changed > least,
                    "{backend:?} rim {k} model {}: {changed} pixels changed",
                    model.id()
                );
            }
        }
    }
}
