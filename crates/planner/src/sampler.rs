//! Seeded sampling of 2-D points (Algorithm 2, lines 2-5).
//!
//! Every random choice flows from one `ChaCha8` stream seeded by the caller, so
//! the same problem and seed give a bit-identical tree.

use glam::DVec2;
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};

/// Draws goal-biased or uniform samples in a box.
#[derive(Debug, Clone)]
pub struct Sampler {
    rng: ChaCha8Rng,
    min_m: DVec2,
    size_m: DVec2,
}

impl Sampler {
    /// A sampler over the box `[min_m, max_m]`, seeded with `seed`.
    #[must_use]
    pub fn new(seed: u64, min_m: DVec2, max_m: DVec2) -> Self {
        Self {
            rng: ChaCha8Rng::seed_from_u64(seed),
            min_m,
            size_m: (max_m - min_m).max(DVec2::ZERO),
        }
    }

    /// A uniform number in `[0, 1)` with 53 random bits.
    #[expect(
        clippy::cast_precision_loss,
        reason = "2^53 and a 53-bit integer are exact in f64"
    )]
    pub fn unit(&mut self) -> f64 {
        const SCALE: f64 = 1.0 / (1u64 << 53) as f64;
        (self.rng.next_u64() >> 11) as f64 * SCALE
    }

    /// The goal with probability `goal_bias`, otherwise a uniform point in the box.
    pub fn sample(&mut self, goal_m: DVec2, goal_bias: f64) -> DVec2 {
        if goal_bias > 0.0 && self.unit() < goal_bias {
            return goal_m;
        }
        let x = self.unit();
        let y = self.unit();
        self.min_m + self.size_m * DVec2::new(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_samples() {
        let mut a = Sampler::new(7, DVec2::ZERO, DVec2::splat(100.0));
        let mut b = Sampler::new(7, DVec2::ZERO, DVec2::splat(100.0));
        for _ in 0..100 {
            assert_eq!(a.sample(DVec2::ONE, 0.3), b.sample(DVec2::ONE, 0.3));
        }
    }

    #[test]
    fn samples_stay_in_the_box() {
        let mut sampler = Sampler::new(1, DVec2::new(-5.0, 10.0), DVec2::new(5.0, 20.0));
        for _ in 0..1000 {
            let point = sampler.sample(DVec2::ZERO, 0.0);
            assert!(point.x >= -5.0 && point.x < 5.0 && point.y >= 10.0 && point.y < 20.0);
        }
    }
}
