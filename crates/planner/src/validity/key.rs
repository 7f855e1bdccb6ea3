//! The bits a verdict of the validity check depends on in one search, and
//! the maps keyed by them: the memos of the search from the root
//! (`vorrt::clearances`, decision 59) and the legs judged so far
//! ([`LegPrefixes`](super::LegPrefixes), decision 70).

use super::EncounterState;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use vorrt_jfs::Leg;

/// A hasher for keys of 64-bit words (the memo's): one multiply and rotate
/// a word (the Firefox hasher's mix), where the standard `SipHash` took about
/// 400 instructions a key, 2 % of a campaign's (decision 66). The memo is
/// only looked up, never iterated, so the hasher changes no verdict.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct WordHasher {
    hash: u64,
}

impl WordHasher {
    /// The Firefox hasher's multiplier (a fixed odd constant).
    const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

    fn add(&mut self, word: u64) {
        self.hash = (self.hash.rotate_left(5) ^ word).wrapping_mul(Self::SEED);
    }
}

impl Hasher for WordHasher {
    fn finish(&self) -> u64 {
        self.hash
    }

    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
    }

    fn write_u64(&mut self, word: u64) {
        self.add(word);
    }

    fn write_usize(&mut self, word: usize) {
        self.add(word as u64);
    }
}

/// A map keyed by words, hashed by [`WordHasher`].
pub(crate) type WordMap<V> = HashMap<Vec<u64>, V, BuildHasherDefault<WordHasher>>;

/// The bits of everything a verdict depends on in one search: the leg, its
/// start time and the encounters in force (exact: `-0.0` is not `0.0`).
pub(crate) fn key_of(leg: &Leg, start_elapsed_s: f64, state: &EncounterState) -> Vec<u64> {
    let mut key = Vec::with_capacity(15 + 7 * state.latches.len() + state.alterations.len());
    key.extend(
        [
            leg.start_m.x,
            leg.start_m.y,
            leg.start_course_rad,
            leg.course_rad,
            leg.turn_rad,
            leg.turn_radius_m,
            leg.straight_m,
            leg.speed_mps,
            start_elapsed_s,
        ]
        .map(f64::to_bits),
    );
    match leg.speed_change {
        Some(change) => key.extend([
            1,
            change.start_speed_mps.to_bits(),
            change.rate_mps2.to_bits(),
        ]),
        None => key.push(0),
    }
    for latch in &state.latches {
        match latch {
            Some(latch) => key.extend([
                1 + latch.encounter as u64,
                latch.reference_course_rad.to_bits(),
                latch.reference_speed_mps.to_bits(),
                latch.latched_at_s.to_bits(),
                latch.risk_distance_m.map_or(u64::MAX, f64::to_bits),
                u64::from(latch.risk_distance_m.is_some()),
            ]),
            None => key.push(0),
        }
    }
    key.extend(state.alterations.iter().map(|altered| altered.to_bits()));
    match state.turn_seen {
        Some(seen) => key.extend([
            1,
            seen.course_before_rad.to_bits(),
            seen.until_elapsed_s.to_bits(),
        ]),
        None => key.push(0),
    }
    key
}

/// The key of `leg` less its straight run ([`key_of`] of the leg with none)
/// from `start_elapsed_s` with `state`: the same for every leg that makes
/// the same turn from the same start, whatever its straight run.
pub(crate) fn start_key_of(leg: &Leg, start_elapsed_s: f64, state: &EncounterState) -> Vec<u64> {
    let turn = Leg {
        straight_m: 0.0,
        ..*leg
    };
    key_of(&turn, start_elapsed_s, state)
}
