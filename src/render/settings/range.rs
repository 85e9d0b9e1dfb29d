//! A number field's rule: the values it takes, as bounds that may be open or infinite, with
//! what a control should span where that differs (an unbounded rule, or one much wider than
//! useful), and the words for a part of the rule that is not a range ("a power of two"), which
//! the type's `validate` checks.

use super::Value;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub min: f64,
    pub max: f64,
    /// Whether `min` and `max` themselves are refused.
    pub exclusive: [bool; 2],
    /// What a control spans (None: `min` to `max`, both finite then).
    pub slider: Option<[f64; 2]>,
    /// The part of the rule that is not a range, in a few words.
    pub rule: Option<&'static str>,
}

const INF: f64 = f64::INFINITY;

impl Range {
    const fn new(min: f64, max: f64, exclusive: [bool; 2]) -> Range {
        Range { min, max, exclusive, slider: None, rule: None }
    }

    /// `[min, max]`.
    pub const fn closed(min: f64, max: f64) -> Range {
        Range::new(min, max, [false, false])
    }

    /// `(min, max)`.
    pub const fn open(min: f64, max: f64) -> Range {
        Range::new(min, max, [true, true])
    }

    /// `(min, max]`.
    pub const fn above_up_to(min: f64, max: f64) -> Range {
        Range::new(min, max, [true, false])
    }

    /// Finite and `>= min`.
    pub const fn at_least(min: f64) -> Range {
        Range::new(min, INF, [false, true])
    }

    /// Finite and `> min`.
    pub const fn above(min: f64) -> Range {
        Range::new(min, INF, [true, true])
    }

    /// Any finite number.
    pub const fn finite() -> Range {
        Range::new(-INF, INF, [true, true])
    }

    /// An unsigned 32-bit count, at least `min`.
    pub const fn count(min: f64) -> Range {
        Range::closed(min, u32::MAX as f64)
    }

    /// The same, within plus or minus `largest` (a field stored as a 32-bit float holds no
    /// larger finite number).
    pub const fn within(self, largest: f64) -> Range {
        let low = if self.min < -largest { (-largest, false) } else { (self.min, self.exclusive[0]) };
        let high = if self.max > largest { (largest, false) } else { (self.max, self.exclusive[1]) };
        Range { min: low.0, max: high.0, exclusive: [low.1, high.1], ..self }
    }

    /// A control spans `lo` to `hi` (within the rule).
    pub const fn slider(self, lo: f64, hi: f64) -> Range {
        Range { slider: Some([lo, hi]), ..self }
    }

    /// The part of the rule that is not a range, which `validate` checks.
    pub const fn rule(self, text: &'static str) -> Range {
        Range { rule: Some(text), ..self }
    }

    /// Whether `x` keeps the range (NaN never does).
    pub fn contains(&self, x: f64) -> bool {
        let low = if self.exclusive[0] { x > self.min } else { x >= self.min };
        let high = if self.exclusive[1] { x < self.max } else { x <= self.max };
        low && high
    }

    /// What a control spans.
    pub fn slider_bounds(&self) -> [f64; 2] {
        self.slider.unwrap_or([self.min, self.max])
    }

    /// The range in words: "in [0, 1]", "finite and >= 0", "finite".
    pub fn text(&self) -> String {
        let [open_min, open_max] = self.exclusive;
        let (min, max) = (written(self.min), written(self.max));
        match (self.min.is_finite(), self.max.is_finite()) {
            (true, true) => {
                let (l, r) = (if open_min { '(' } else { '[' }, if open_max { ')' } else { ']' });
                format!("in {l}{min}, {max}{r}")
            }
            (true, false) => format!("finite and {} {min}", if open_min { ">" } else { ">=" }),
            (false, true) => format!("finite and {} {max}", if open_max { "<" } else { "<=" }),
            (false, false) => "finite".to_string(),
        }
    }

    /// Why `x` is refused by the range.
    pub fn refusal(&self, x: f64) -> String {
        format!("must be {}, got {}", self.text(), written(x))
    }

    /// Why `x` is refused by the whole rule ("must be a power of two in [64, 8192]"), for the
    /// `validate` that checks its part that is not a range.
    pub fn rule_refusal(&self, x: f64) -> String {
        match self.rule {
            Some(rule) => format!("must be {rule} {}, got {}", self.text(), written(x)),
            None => self.refusal(x),
        }
    }

    /// The range for front ends: `min`, `max` (the rule's bounds; an int field's as ints),
    /// `exclusive`, `slider` and, where there is one, `rule`.
    pub fn describe(&self, int: bool) -> Vec<(&'static str, Value)> {
        let number = |x: f64| if int && x.is_finite() { Value::Int(x as i64) } else { Value::Float(x) };
        let [lo, hi] = self.slider_bounds();
        let mut d = vec![
            ("min", number(self.min)),
            ("max", number(self.max)),
            ("exclusive", Value::List(self.exclusive.iter().map(|&e| Value::Bool(e)).collect())),
            ("slider", Value::List(vec![number(lo), number(hi)])),
        ];
        if let Some(rule) = self.rule {
            d.push(("rule", Value::Text(rule.to_string())));
        }
        d
    }
}

/// A number as an error writes it: with an exponent where it is huge (3.4028235e38, not 39
/// digits).
fn written(x: f64) -> String {
    if x.abs() >= 1e16 {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_keep_or_refuse_their_ends_and_nan() {
        assert!(Range::closed(0.0, 1.0).contains(1.0) && !Range::open(0.0, 1.0).contains(1.0));
        assert!(!Range::at_least(0.0).contains(INF) && Range::at_least(0.0).contains(0.0));
        assert!(!Range::finite().contains(f64::NAN) && Range::finite().contains(-1e300));
        assert_eq!(Range::above(0.0).refusal(0.0), "must be finite and > 0, got 0");
        let size = Range::closed(64.0, 8192.0).rule("a power of two");
        assert_eq!(size.refusal(32.0), "must be in [64, 8192], got 32");
        assert_eq!(size.rule_refusal(1000.0), "must be a power of two in [64, 8192], got 1000");
        assert_eq!(
            Range::at_least(0.0).within(f32::MAX as f64).refusal(1e300),
            "must be in [0, 3.4028234663852886e38], got 1e300"
        );
        assert_eq!(Range::at_least(0.0).within(f64::INFINITY), Range::at_least(0.0));
        assert_eq!(Range::at_least(0.0).slider(0.0, 8.0).slider_bounds(), [0.0, 8.0]);
    }
}
