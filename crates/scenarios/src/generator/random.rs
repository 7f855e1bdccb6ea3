//! The seeded random streams of the generator, its uniform draws and the
//! rounding that keeps generated files readable.

use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};

/// The random stream of scenario `index` of a batch seeded with `seed`.
#[must_use]
pub fn scenario_stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    rng
}

/// The stream of a scenario's behaviour draws: separate from its geometry's.
pub(super) fn behaviour_stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xB3A7_1F0E_5EED_0001);
    rng.set_stream(index);
    rng
}

/// The simulation seed of scenario `index` of a batch seeded with `seed`
/// (`SplitMix64` of the two): what the batch runner simulates it with, and what
/// generated scenarios carry in their `seed` field, so that
/// `vorrt simulate` on a generated file repeats its batch run.
#[must_use]
pub fn run_seed(seed: u64, index: u64) -> u64 {
    splitmix64(seed ^ splitmix64(index.wrapping_add(0x5EED)))
}

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A uniform draw in `[low, high)`.
#[expect(clippy::cast_precision_loss, reason = "53-bit values, exact in f64")]
pub(super) fn uniform(rng: &mut ChaCha8Rng, low: f64, high: f64) -> f64 {
    let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    low + (high - low) * unit
}

/// A uniform draw in the range `(low, high)`.
pub(super) fn uniform_in(rng: &mut ChaCha8Rng, (low, high): (f64, f64)) -> f64 {
    uniform(rng, low, high)
}

/// Rounds to `digits` decimals so that files stay readable.
pub(super) fn round_to(value: f64, digits: i32) -> f64 {
    let scale = 10f64.powi(digits);
    (value * scale).round() / scale
}
