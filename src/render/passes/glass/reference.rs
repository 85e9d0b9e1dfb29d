//! The CPU twin of the glass stage: one pixel's glass fragments peeled and composited as the
//! passes do (`peeled`), and the exact rule they approach (`over`): the fragments in depth
//! order, each laid over what lies behind it, in linear light.

/// One glass fragment of a pixel: its linear depth, linear colour and opacity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    pub depth: f32,
    pub color: [f32; 3],
    pub opacity: f32,
}

/// The exact rule: the fragments in front of the opaque surface (at `opaque_depth`, colour
/// `opaque`), from the farthest to the nearest, each laid over the rest:
/// c = opacity color + (1 - opacity) c.
pub fn over(fragments: &[Fragment], opaque_depth: f32, opaque: [f32; 3]) -> [f32; 3] {
    let mut sorted: Vec<&Fragment> = fragments.iter().filter(|f| f.depth < opaque_depth).collect();
    sorted.sort_by(|a, b| b.depth.total_cmp(&a.depth));
    sorted
        .iter()
        .fold(opaque, |c, f| std::array::from_fn(|i| f.opacity * f.color[i] + (1.0 - f.opacity) * c[i]))
}

/// What the passes compute: `layers` peels, each taking the nearest fragment strictly behind the
/// last one taken and in front of the opaque surface, added under the sum so far
/// (premultiplied: sum += (1 - sum.a) (opacity color, opacity)); then the sum over `opaque`.
pub fn peeled(fragments: &[Fragment], opaque_depth: f32, opaque: [f32; 3], layers: u32) -> [f32; 3] {
    let mut sum = [0.0f32; 4];
    let mut last = 0.0f32;
    for _ in 0..layers {
        let next = fragments
            .iter()
            .filter(|f| f.depth > last && f.depth < opaque_depth)
            .min_by(|a, b| a.depth.total_cmp(&b.depth));
        let Some(f) = next else { break };
        let layer = [f.color[0] * f.opacity, f.color[1] * f.opacity, f.color[2] * f.opacity, f.opacity];
        let keep = 1.0 - sum[3];
        sum = std::array::from_fn(|i| sum[i] + keep * layer[i]);
        last = f.depth;
    }
    std::array::from_fn(|i| sum[i] + (1.0 - sum[3]) * opaque[i])
}

#[cfg(test)]
mod tests {
    use super::*;

    const RED: [f32; 3] = [1.0, 0.0, 0.0];

    fn frags() -> Vec<Fragment> {
        vec![
            Fragment { depth: 2.0, color: [0.0, 0.0, 1.0], opacity: 0.5 },
            Fragment { depth: 3.0, color: [0.0, 1.0, 0.0], opacity: 0.4 },
            Fragment { depth: 9.0, color: [1.0, 1.0, 1.0], opacity: 0.9 },
        ]
    }

    #[test]
    fn peeling_is_the_exact_rule_in_any_order() {
        let exact = over(&frags(), 5.0, RED);
        // blue 0.5 over green 0.4 over red: 0.5 (0,0,1) + 0.5 (0.4 (0,1,0) + 0.6 (1,0,0))
        let by_hand = [0.3, 0.2, 0.5];
        assert!(exact.iter().zip(by_hand).all(|(a, b)| (a - b).abs() < 1e-6), "{exact:?}");
        let mut f = frags();
        for _ in 0..3 {
            f.rotate_left(1);
            assert_eq!(peeled(&f, 5.0, RED, 4), exact);
        }
    }

    #[test]
    fn fewer_layers_drop_the_farthest() {
        let one = peeled(&frags(), 5.0, RED, 1);
        assert_eq!(one, over(&frags()[..1], 5.0, RED));
        assert_ne!(one, over(&frags(), 5.0, RED));
        // nothing in front of the surface: the surface
        assert_eq!(peeled(&frags(), 1.0, RED, 4), RED);
    }
}
