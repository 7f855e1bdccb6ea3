//! How the generated targets move.

use super::random::uniform;
use crate::scenario::Behaviour;
use rand_chacha::ChaCha8Rng;
use rand_core::RngCore;
use serde::{Deserialize, Serialize};

/// How the generated targets move: the [`Behaviour`] every target gets, with
/// the sudden turns drawn per target.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TargetBehaviour {
    /// [`Behaviour::ConstantToGoal`]: the paper's non-manoeuvring targets.
    #[default]
    Constant,
    /// [`Behaviour::Colregs`]: targets give way to ownship when the rules say so.
    Colregs,
    /// [`Behaviour::Noisy`] with these standard deviations.
    Noisy {
        /// Course noise, degrees.
        course_sigma_deg: f64,
        /// Speed noise, knots.
        speed_sigma_kn: f64,
    },
    /// [`Behaviour::SuddenTurn`]: each target turns 30-90° to a random side
    /// at a random time between 25 % and 75 % of its time to its closest
    /// approach with ownship (open sea) or of its time to the crossing line
    /// (TSS).
    SuddenTurn,
}

/// Default course noise of [`TargetBehaviour::Noisy`], degrees.
pub const DEFAULT_COURSE_SIGMA_DEG: f64 = 5.0;
/// Default speed noise of [`TargetBehaviour::Noisy`], knots.
pub const DEFAULT_SPEED_SIGMA_KN: f64 = 0.5;

impl TargetBehaviour {
    /// Parses a command-line name: `constant`, `colregs`, `noisy` (default
    /// sigmas) or `sudden-turn`.
    ///
    /// # Errors
    /// The accepted names, when `name` is none of them.
    pub fn from_name(name: &str) -> Result<Self, String> {
        match name {
            "constant" => Ok(Self::Constant),
            "colregs" => Ok(Self::Colregs),
            "noisy" => Ok(Self::Noisy {
                course_sigma_deg: DEFAULT_COURSE_SIGMA_DEG,
                speed_sigma_kn: DEFAULT_SPEED_SIGMA_KN,
            }),
            "sudden-turn" | "sudden_turn" => Ok(Self::SuddenTurn),
            other => Err(format!(
                "unknown behaviour {other:?}: expected constant, colregs, noisy or sudden-turn"
            )),
        }
    }

    /// The command-line name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Constant => "constant",
            Self::Colregs => "colregs",
            Self::Noisy { .. } => "noisy",
            Self::SuddenTurn => "sudden-turn",
        }
    }

    /// The behaviour of one target whose event time scale is `time_scale_s`.
    pub(super) fn behaviour(&self, rng: &mut ChaCha8Rng, time_scale_s: f64) -> Behaviour {
        match *self {
            Self::Constant => Behaviour::ConstantToGoal,
            Self::Colregs => Behaviour::Colregs,
            Self::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            } => Behaviour::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            },
            Self::SuddenTurn => {
                let at_s = (uniform(rng, 0.25, 0.75) * time_scale_s).round();
                let side = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
                let turn_deg = side * uniform(rng, 30.0, 90.0).round();
                Behaviour::SuddenTurn { at_s, turn_deg }
            }
        }
    }
}
