//! Back-face culling only where it cannot change the image: a mesh that encloses solids
//! (`mesh::enclosure`), seen by a camera whose near plane lies wholly in front of the mesh's
//! bounding sphere. Every ray the camera casts then starts outside every shell and meets an outer
//! side first, so the faces that turn their inner side to the camera are always hidden, and
//! skipping them only saves their rasterisation (about half of a closed mesh's triangles).
//! Shadow maps are fitted around the whole scene, so there the enclosure alone decides.

use glam::DVec3;

use crate::mesh::enclosure::Enclosure;

use super::scene::camera::ResolvedCamera;
use super::scene::SceneItem;

/// The winding wgpu culls (`Face::Back`: clockwise on screen) to skip a mesh's inner sides, or
/// None when the mesh encloses nothing. A mirroring transform swaps the windings.
pub fn inner_face(enclosure: Option<Enclosure>, mirrored: bool) -> Option<wgpu::Face> {
    let inner_is_back = match enclosure? {
        Enclosure::Outward => !mirrored,
        Enclosure::Inward => mirrored,
    };
    Some(if inner_is_back { wgpu::Face::Back } else { wgpu::Face::Front })
}

/// Whether the near plane of `cam` lies wholly in front of the sphere of `radius` about `center`
/// (both in the mesh's own coordinates) placed by `item`: the camera sees the mesh only from
/// outside it. The transform makes the sphere an ellipsoid, whose nearest depth is its centre's
/// less the radius times the length of the depth row of the linear part.
pub fn seen_from_outside(item: &SceneItem, center: DVec3, radius: f64, cam: &ResolvedCamera) -> bool {
    let to_view = cam.view * item.model_matrix();
    let depth = -to_view.transform_point3(center).z;
    let depth_row = DVec3::new(to_view.x_axis.z, to_view.y_axis.z, to_view.z_axis.z);
    let nearest = depth - radius * depth_row.length();
    // a margin for rounding in the GPU's float32 clip test
    nearest > cam.near + 1e-5 * (depth.abs() + cam.near.abs())
}

/// What one mesh skips: in the camera's passes, and in the shadow map.
pub fn culls(
    item: &SceneItem,
    enclosure: Option<Enclosure>,
    center: DVec3,
    radius: f64,
    cam: &ResolvedCamera,
) -> (Option<wgpu::Face>, Option<wgpu::Face>) {
    let inner = inner_face(enclosure, item.mirrors());
    let camera = inner.filter(|_| seen_from_outside(item, center, radius, cam));
    (camera, inner)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_inner_side_follows_winding_and_mirroring() {
        assert_eq!(inner_face(None, false), None);
        assert_eq!(inner_face(Some(Enclosure::Outward), false), Some(wgpu::Face::Back));
        assert_eq!(inner_face(Some(Enclosure::Outward), true), Some(wgpu::Face::Front));
        assert_eq!(inner_face(Some(Enclosure::Inward), false), Some(wgpu::Face::Front));
        assert_eq!(inner_face(Some(Enclosure::Inward), true), Some(wgpu::Face::Back));
    }
}
