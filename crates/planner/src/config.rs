//! Planner configuration, with the paper's values as defaults.

use crate::error::PlannerError;
use crate::plan::RejectionCause;
use serde::{Deserialize, Serialize};
use vorrt_colregs::RuleParameters;
use vorrt_jfs::{InstantTurn, OwnshipModel, RateLimitedTurn};

/// How the nearest tree node to a sample is found.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NearestIndex {
    /// A scan over the node positions, stored contiguously: the reference
    /// the others give the same answer as.
    Linear,
    /// An R*-tree (`rstar`), filled as nodes are accepted.
    RTree,
    /// The default: the nodes binned in square cells of 1600 m with their
    /// bounding boxes; a query scans the cells that can hold a node nearer
    /// than the best so far. Same answer as `Linear`, ties included (see
    /// `docs/history/performance.md`, "2026-11-30: cheaper retries, a grid nearest-node
    /// index").
    #[default]
    Grid,
}

/// How ownship turns along the plan it is given.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Turning {
    /// The paper's joint step: the course changes at a node, instantaneously
    /// (bounded by `max_turn_per_step_rad`); the plan is the tree's branch.
    Instant,
    /// At most the default rate of turn of ownship's length and speed
    /// (`vorrt_jfs::default_turn_rate_rad_s`): the branch is simplified into
    /// the fewest legs the validity check accepts, joined by arcs.
    #[default]
    FromLength,
    /// At most this rate of turn, radians per second; as `FromLength`
    /// otherwise.
    MaxRate {
        /// Largest rate of turn, radians per second.
        max_turn_rate_rad_s: f64,
    },
}

impl Turning {
    /// The largest rate of turn of ownship (`length_m`, `speed_mps`),
    /// radians per second; `None` for instantaneous turns.
    #[must_use]
    pub fn max_turn_rate_rad_s(self, length_m: f64, speed_mps: f64) -> Option<f64> {
        match self {
            Turning::Instant => None,
            Turning::FromLength => Some(vorrt_jfs::default_turn_rate_rad_s(length_m, speed_mps)),
            Turning::MaxRate {
                max_turn_rate_rad_s,
            } => Some(max_turn_rate_rad_s),
        }
    }

    /// How ownship (`length_m`, service speed `speed_mps`) sails: the one
    /// place a [`Turning`] becomes a motion model, for the planner's plans,
    /// the closed loop that sails them and the evasive fallback alike. A
    /// rate-limited turn at [`max_turn_rate_rad_s`](Self::max_turn_rate_rad_s),
    /// or, for `Instant`, a change of course at once of any size (the plan's
    /// legs then carry the tree's bounded steps).
    ///
    /// ```
    /// use vorrt_planner::Turning;
    /// use vorrt_jfs::OwnshipModel;
    /// // A 300 m ship at 6 m/s turns on 3 lengths (0.38°/s).
    /// let OwnshipModel::RateLimited(model) = Turning::FromLength.ownship_model(300.0, 6.0) else {
    ///     panic!("a rate of turn");
    /// };
    /// assert!((model.turn_radius_m - 900.0).abs() < 1e-6);
    /// assert!(matches!(Turning::Instant.ownship_model(300.0, 6.0), OwnshipModel::Instant(_)));
    /// ```
    #[must_use]
    pub fn ownship_model(self, length_m: f64, speed_mps: f64) -> OwnshipModel {
        match self.max_turn_rate_rad_s(length_m, speed_mps) {
            Some(rate) => OwnshipModel::RateLimited(RateLimitedTurn::from_rate(speed_mps, rate)),
            None => OwnshipModel::Instant(InstantTurn {
                max_turn_rad: std::f64::consts::PI,
            }),
        }
    }
}

/// Which COLREGs duties the planner's validity check enforces: all of them,
/// or, as a graded fallback when no fully compliant path exists, fewer.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Compliance {
    /// Every rule: the directions of rules 14, 15 and 17 and the manner of
    /// the action (readily apparent, early, held until past: rules 8, 16).
    #[default]
    Full,
    /// The directions of rules 14, 15 and 17 only: a smaller, later or
    /// shorter alteration is allowed (a departure from rules 8 and 16).
    Directions,
    /// Clearance and velocity obstacles, and no port turn that makes a
    /// vessel a risk of collision (decision 57): a departure from the
    /// steering rules to avoid immediate danger (rules 2(b), 17(b)), never
    /// one that creates a danger.
    SafetyOnly,
}

impl Compliance {
    /// The next, weaker level to fall back to, if any.
    #[must_use]
    pub fn relaxed(self) -> Option<Compliance> {
        match self {
            Compliance::Full => Some(Compliance::Directions),
            Compliance::Directions => Some(Compliance::SafetyOnly),
            Compliance::SafetyOnly => None,
        }
    }

    /// Whether the validity check at this level can refuse a move for
    /// `cause`: clearance, velocity obstacles and a port turn toward a
    /// vessel that makes it a risk (decision 57) at every level; the
    /// manner of the action (its size, when it begins, that it is held:
    /// rules 8, 16, checked by `vorrt_colregs::check_alteration` and
    /// `check_action`) only at `Full`; the other COLREGs duties (the
    /// directions, `check_motion` and `check_heading`) at `Full` and
    /// `Directions`. This is what [`crate::safety::SafetyChecker`] applies at each
    /// level; a search at a stricter level that refused nothing for a cause
    /// the weaker level does not check is the search the weaker level would
    /// make ([`Planner::would_repeat`](crate::Planner::would_repeat)).
    #[must_use]
    pub fn checks(self, cause: RejectionCause) -> bool {
        use vorrt_colregs::ManeuverViolation::{
            AlterationNotHeld, InsufficientAlteration, LateAction, PortTurnTowardVessel,
        };
        match cause {
            RejectionCause::VelocityObstacle
            | RejectionCause::Clearance
            | RejectionCause::ClearanceAhead
            | RejectionCause::Constraint(_)
            // A port turn onto a vessel that made it a risk (decision 57):
            // a departure that creates a danger, never one that avoids it
            // (rules 2(b), 17(b)).
            | RejectionCause::Colregs(PortTurnTowardVessel) => true,
            RejectionCause::Colregs(InsufficientAlteration | LateAction | AlterationNotHeld) => {
                self == Compliance::Full
            }
            RejectionCause::Colregs(_) => self != Compliance::SafetyOnly,
        }
    }
}

/// How much of the search one call of [`Planner::plan_with`](crate::Planner::plan_with)
/// runs: every phase of every attempt, or only the goal-biased first phase.
///
/// A closed loop retrying for a fully compliant plan while it sails a
/// fallback plan asks again every few seconds, so each retry is one more
/// draw: measured on the closed loop (`docs/history/performance.md`, "2026-11-30:
/// cheaper retries, a grid nearest-node index"), 14 % of the successful attempts succeed in phase 2 while
/// phase 2 draws half the samples of an attempt that fails, on the larger
/// tree (dearer nearest-node scans). `FirstPhase` keeps the restarts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SearchEffort {
    /// Both phases of every attempt (Algorithm 2, erratum 4): [`Planner::plan`](crate::Planner::plan).
    #[default]
    Full,
    /// Only the first, goal-biased phase of every attempt (restarts kept).
    FirstPhase,
    /// The search from the root; the tree of [`Full`](Self::Full) only
    /// where that search was refused by the planner's user constraint
    /// (land, a no-go area, a lane: obstacles its one- and two-alteration
    /// manoeuvres cannot get round), else none (decision 66). With
    /// instantaneous turns, which have no search from the root, as `Full`.
    /// What a closed loop asks of the stricter levels of its graded
    /// fallback.
    FullWhereConstrained,
    /// As [`FullWhereConstrained`](Self::FullWhereConstrained), with the
    /// tree of [`FirstPhase`](Self::FirstPhase).
    FirstPhaseWhereConstrained,
}

impl SearchEffort {
    /// How many phases of each attempt the tree grows.
    ///
    /// ```
    /// use vorrt_planner::SearchEffort;
    /// assert_eq!(SearchEffort::Full.phases(), 2);
    /// assert_eq!(SearchEffort::FirstPhaseWhereConstrained.phases(), 1);
    /// ```
    #[must_use]
    pub fn phases(self) -> usize {
        match self {
            Self::Full | Self::FullWhereConstrained => 2,
            Self::FirstPhase | Self::FirstPhaseWhereConstrained => 1,
        }
    }

    /// Whether the tree is grown only where the search from the root was
    /// refused by the user constraint.
    ///
    /// ```
    /// use vorrt_planner::SearchEffort;
    /// assert!(SearchEffort::FullWhereConstrained.tree_only_where_constrained());
    /// assert!(!SearchEffort::FirstPhase.tree_only_where_constrained());
    /// ```
    #[must_use]
    pub fn tree_only_where_constrained(self) -> bool {
        matches!(
            self,
            Self::FullWhereConstrained | Self::FirstPhaseWhereConstrained
        )
    }

    /// The effort whose search asks the same moves as this one's, in the
    /// same order, and then goes on where this one may stop: itself, or for
    /// an effort that grows its tree only where constrained, the one that
    /// always grows it (a search that skips the tree stops where the other
    /// grows it; one that grows it is the other's).
    ///
    /// ```
    /// use vorrt_planner::SearchEffort;
    /// assert_eq!(SearchEffort::FullWhereConstrained.always_growing(), SearchEffort::Full);
    /// assert_eq!(SearchEffort::FirstPhase.always_growing(), SearchEffort::FirstPhase);
    /// ```
    #[must_use]
    pub fn always_growing(self) -> Self {
        match self {
            Self::Full | Self::FullWhereConstrained => Self::Full,
            Self::FirstPhase | Self::FirstPhaseWhereConstrained => Self::FirstPhase,
        }
    }
}

/// Every knob of the VORRT planner.
///
/// Defaults are the paper's where it gives one (`d' = 100 m`, `d_th = 200 m`,
/// 200 accepted nodes per phase) and documented choices where it does not
/// (notes, errata 4, 5, 8 and 10).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PlannerConfig {
    /// `d'`: how far ownship moves toward a sample in one joint forward step,
    /// metres. Paper: 100 m.
    pub step_m: f64,
    /// `d_th`: the clearance every target must keep from ownship along every
    /// segment and, while an encounter is in force, beyond it, measured
    /// between the hulls (reference points stay `d_th` plus half the sum of
    /// the lengths apart). Paper: 200 m in open sea, 100 m in a traffic
    /// separation scheme.
    pub clearance_m: f64,
    /// The passing distance ownship prefers where sea room allows, as a
    /// multiple of `clearance_m` (default 2): the manoeuvre search first
    /// looks for one alteration that passes every target this wide (between
    /// the hulls), and only then for one that keeps `clearance_m`, the hard
    /// floor. Masters' standing orders ask for far more than a small craft's
    /// `d_th` (1-2 nm in open water), and a wider pass leaves room for a vessel
    /// that does not do what it was predicted to. 1 (or less) turns it off.
    pub preferred_clearance_factor: f64,
    /// A node this close to the goal tries a final segment onto it, metres.
    /// Default: `step_m`.
    pub goal_tolerance_m: f64,
    /// Probability of sampling the goal in phase 1 (erratum 5). The paper
    /// samples the goal every time (1.0), which repeats a rejected extension;
    /// 0.5 keeps the bias and lets the tree explore.
    pub goal_bias: f64,
    /// Probability of sampling the goal in phase 2. The paper's phase 2 is
    /// unbiased (0.0), the default.
    pub phase_two_goal_bias: f64,
    /// Accepted nodes per phase (paper: 200).
    pub nodes_per_phase: usize,
    /// Samples (accepted or not) per phase before the phase gives up (erratum 4).
    pub samples_per_phase: usize,
    /// Budgets follow the route: a plan from `start` to `goal` gets at least
    /// this many accepted nodes per phase for each step `d'` of the straight
    /// route, and samples in the same proportion (see
    /// [`PlannerConfig::for_route`]). Default 2.5; 0 turns the scaling off.
    pub nodes_per_route_step: f64,
    /// How many times the whole tree is grown again from the root after both
    /// phases fail.
    pub max_restarts: usize,
    /// Largest course change at one node, radians: a sample that asks for more
    /// is steered toward within this limit (erratum 10: a turn-rate bound).
    /// Default 30° per `d'` (a turning radius of about 190 m at 100 m
    /// steps): on the 22 Imazu cases × 10 seeds it succeeds more often and
    /// gives shorter paths than 45° (209 vs 205 of 220 at 600 nodes a phase,
    /// before goal-facing nearest nodes), while 20° fails far more (185).
    pub max_turn_per_step_rad: f64,
    /// Margin around the start-goal box in which random samples fall, metres.
    pub sampling_margin_m: f64,
    /// Longest look beyond a segment for encounters in force, seconds: the
    /// CPA of the new velocity is checked over this time (cut short where
    /// ownship would reach its goal).
    pub lookahead_s: f64,
    /// Wall-clock budget for one plan, seconds; `None` for no limit. When it
    /// runs out the planner returns [`PlannerError::BudgetExhausted`].
    pub time_budget_s: Option<f64>,
    /// Nearest-node search.
    pub nearest_index: NearestIndex,
    /// How ownship turns: instantaneously as in the paper, or at a bounded
    /// rate of turn (the default), in which case the plan is the tree's
    /// branch simplified into legs joined by arcs.
    pub turning: Turning,
    /// How fast ownship changes speed (slowing down or speeding up back to
    /// its service speed), m/s²; `None` (the default): from its length and
    /// service speed, stopping in 15 lengths
    /// (`vorrt_jfs::default_speed_change_mps2`). With `Turning::Instant`
    /// speed changes are instantaneous, as turns are.
    pub speed_change_mps2: Option<f64>,
    /// Which COLREGs duties the validity check enforces (default: all).
    pub compliance: Compliance,
    /// The COLREGs constants: MTD, sectors, stand-on tolerances.
    pub rules: RuleParameters,
}

impl Default for PlannerConfig {
    fn default() -> Self {
        Self {
            step_m: 100.0,
            clearance_m: 200.0,
            preferred_clearance_factor: 2.0,
            goal_tolerance_m: 100.0,
            goal_bias: 0.5,
            phase_two_goal_bias: 0.0,
            nodes_per_phase: 200,
            samples_per_phase: 4000,
            nodes_per_route_step: 2.5,
            max_restarts: 3,
            max_turn_per_step_rad: 30f64.to_radians(),
            sampling_margin_m: 2.0 * 1852.0,
            lookahead_s: 1800.0,
            time_budget_s: None,
            nearest_index: NearestIndex::Grid,
            turning: Turning::FromLength,
            speed_change_mps2: None,
            compliance: Compliance::Full,
            rules: RuleParameters::default(),
        }
    }
}

/// The largest tree the planner will grow, whatever the configuration says:
/// bounds memory (about 100 bytes a node plus 40 bytes a node per target).
pub const MAX_NODES_PER_PHASE: usize = 100_000;

/// The most samples per phase the planner accepts as configuration.
pub const MAX_SAMPLES_PER_PHASE: usize = 10_000_000;

/// The largest length (metres) or time (seconds) a configuration may give:
/// keeps every distance, time and area the planner computes finite.
pub const MAX_LENGTH_OR_TIME: f64 = 1e8;

/// The largest `nodes_per_route_step` the planner accepts.
pub const MAX_NODES_PER_ROUTE_STEP: f64 = 1_000.0;

/// The most restarts the planner accepts as configuration.
pub const MAX_RESTARTS: usize = 1_000;

/// The error for `field` holding `value` where `expected` was wanted.
fn invalid(field: &'static str, value: f64, expected: &'static str) -> Result<(), PlannerError> {
    Err(PlannerError::InvalidConfig {
        field,
        value,
        expected,
    })
}

impl PlannerConfig {
    /// The configuration a plan over a straight route of `route_m` metres
    /// runs with: budgets that follow the route length, so that long routes
    /// plan with default settings.
    ///
    /// `nodes_per_phase` becomes `max(nodes_per_phase, ceil(k × route_m /
    /// step_m))` with `k = nodes_per_route_step` (a branch to the goal needs
    /// `route_m / step_m` nodes, and half the samples are random), at most
    /// [`MAX_NODES_PER_PHASE`]; `samples_per_phase` grows in the same
    /// proportion, at most [`MAX_SAMPLES_PER_PHASE`]. A short route keeps the
    /// configured budgets exactly: with the defaults (200 nodes, k = 2.5) any
    /// route up to 8 km; with the bundled fixtures' 600 nodes, up to 24 km.
    ///
    /// ```
    /// use vorrt_planner::PlannerConfig;
    /// let config = PlannerConfig::default();
    /// assert_eq!(config.for_route(5_000.0), config);
    /// let long = config.for_route(30.0 * 1852.0);
    /// assert_eq!(long.nodes_per_phase, 1389);
    /// assert_eq!(long.samples_per_phase, 27_780);
    /// ```
    #[must_use]
    #[expect(
        clippy::cast_precision_loss,
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "node and sample counts are at most 1e7, exact in f64; the \
                  rounded-up budgets are positive and clamped to those maxima"
    )]
    pub fn for_route(&self, route_m: f64) -> PlannerConfig {
        let needed = (self.nodes_per_route_step * route_m / self.step_m).ceil();
        // NaN (a non-finite route) keeps the configured budgets.
        if needed.is_nan() || needed <= self.nodes_per_phase as f64 || self.nodes_per_phase == 0 {
            return *self;
        }
        let nodes = needed.min(MAX_NODES_PER_PHASE as f64) as usize;
        let scale = nodes as f64 / self.nodes_per_phase as f64;
        let samples = (self.samples_per_phase as f64 * scale)
            .ceil()
            .min(MAX_SAMPLES_PER_PHASE as f64) as usize;
        PlannerConfig {
            nodes_per_phase: nodes.max(self.nodes_per_phase),
            samples_per_phase: samples.max(nodes).max(self.samples_per_phase),
            ..*self
        }
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`PlannerError::InvalidConfig`] naming the first field out of range.
    pub fn validate(&self) -> Result<(), PlannerError> {
        self.validate_geometry()?;
        self.validate_budgets()?;
        self.validate_rates()?;
        self.rules.validate().map_err(PlannerError::from)
    }

    /// The lengths, times, factors, probabilities and turn per step.
    fn validate_geometry(&self) -> Result<(), PlannerError> {
        let positive = [
            ("step_m", self.step_m),
            ("clearance_m", self.clearance_m),
            ("goal_tolerance_m", self.goal_tolerance_m),
            ("lookahead_s", self.lookahead_s),
        ];
        for (field, value) in positive {
            if !(value.is_finite() && value > 0.0 && value <= MAX_LENGTH_OR_TIME) {
                return invalid(field, value, "a number greater than 0 and at most 1e8");
            }
        }
        if !(self.preferred_clearance_factor >= 0.0 && self.preferred_clearance_factor <= 100.0) {
            return invalid(
                "preferred_clearance_factor",
                self.preferred_clearance_factor,
                "a number from 0 to 100",
            );
        }
        if !(self.sampling_margin_m >= 0.0 && self.sampling_margin_m <= MAX_LENGTH_OR_TIME) {
            return invalid(
                "sampling_margin_m",
                self.sampling_margin_m,
                "a number from 0 to 1e8",
            );
        }
        for (field, value) in [
            ("goal_bias", self.goal_bias),
            ("phase_two_goal_bias", self.phase_two_goal_bias),
        ] {
            if !(0.0..=1.0).contains(&value) {
                return invalid(field, value, "a probability in [0, 1]");
            }
        }
        if !(self.max_turn_per_step_rad > 0.0 && self.max_turn_per_step_rad <= std::f64::consts::PI)
        {
            return invalid(
                "max_turn_per_step_rad",
                self.max_turn_per_step_rad,
                "an angle in (0, π]",
            );
        }
        Ok(())
    }

    /// The node, sample and restart budgets.
    #[expect(
        clippy::cast_precision_loss,
        reason = "a count out of range is only reported, as the error's value"
    )]
    fn validate_budgets(&self) -> Result<(), PlannerError> {
        if self.nodes_per_phase == 0 || self.nodes_per_phase > MAX_NODES_PER_PHASE {
            return invalid(
                "nodes_per_phase",
                self.nodes_per_phase as f64,
                "a whole number from 1 to 100000",
            );
        }
        if self.samples_per_phase < self.nodes_per_phase
            || self.samples_per_phase > MAX_SAMPLES_PER_PHASE
        {
            return invalid(
                "samples_per_phase",
                self.samples_per_phase as f64,
                "a whole number from nodes_per_phase to 10000000",
            );
        }
        if !(0.0..=MAX_NODES_PER_ROUTE_STEP).contains(&self.nodes_per_route_step) {
            return invalid(
                "nodes_per_route_step",
                self.nodes_per_route_step,
                "a number from 0 to 1000",
            );
        }
        if self.max_restarts > MAX_RESTARTS {
            return invalid(
                "max_restarts",
                self.max_restarts as f64,
                "a whole number from 0 to 1000",
            );
        }
        Ok(())
    }

    /// The time budget and the rates of turn and of speed change.
    fn validate_rates(&self) -> Result<(), PlannerError> {
        if let Some(budget) = self.time_budget_s
            && !(budget.is_finite() && budget > 0.0)
        {
            return invalid(
                "time_budget_s",
                budget,
                "a finite number of seconds greater than 0",
            );
        }
        if let Turning::MaxRate {
            max_turn_rate_rad_s,
        } = self.turning
            && !(max_turn_rate_rad_s.is_finite() && max_turn_rate_rad_s > 0.0)
        {
            return invalid(
                "turning.max_turn_rate_rad_s",
                max_turn_rate_rad_s,
                "a finite rate of turn greater than 0",
            );
        }
        if let Some(rate) = self.speed_change_mps2
            && !(rate.is_finite() && rate > 0.0)
        {
            return invalid(
                "speed_change_mps2",
                rate,
                "a finite rate of speed change greater than 0 m/s²",
            );
        }
        Ok(())
    }

    /// How fast ownship (`length_m`, service speed `service_speed_mps`)
    /// changes speed, m/s²: infinite for instantaneous turns (the paper's
    /// model has no dynamics), else `speed_change_mps2` or the default from
    /// its length and speed.
    ///
    /// ```
    /// use vorrt_planner::{PlannerConfig, Turning};
    /// let config = PlannerConfig::default();
    /// assert!((config.speed_change_rate_mps2(50.0, 6.0) - 0.024).abs() < 1e-12);
    /// let instant = PlannerConfig { turning: Turning::Instant, ..config };
    /// assert!(instant.speed_change_rate_mps2(50.0, 6.0).is_infinite());
    /// ```
    #[must_use]
    pub fn speed_change_rate_mps2(&self, length_m: f64, service_speed_mps: f64) -> f64 {
        match (self.turning, self.speed_change_mps2) {
            (Turning::Instant, _) => f64::INFINITY,
            (_, Some(rate)) => rate,
            (_, None) => vorrt_jfs::default_speed_change_mps2(length_m, service_speed_mps),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid() {
        PlannerConfig::default().validate().expect("defaults");
    }

    #[test]
    fn each_bad_field_is_named() {
        let cases: [(PlannerConfig, &str); 7] = [
            (
                PlannerConfig {
                    speed_change_mps2: Some(0.0),
                    ..PlannerConfig::default()
                },
                "speed_change_mps2",
            ),
            (
                PlannerConfig {
                    step_m: 0.0,
                    ..PlannerConfig::default()
                },
                "step_m",
            ),
            (
                PlannerConfig {
                    clearance_m: f64::NAN,
                    ..PlannerConfig::default()
                },
                "clearance_m",
            ),
            (
                PlannerConfig {
                    preferred_clearance_factor: f64::NAN,
                    ..PlannerConfig::default()
                },
                "preferred_clearance_factor",
            ),
            (
                PlannerConfig {
                    goal_bias: 1.5,
                    ..PlannerConfig::default()
                },
                "goal_bias",
            ),
            (
                PlannerConfig {
                    nodes_per_phase: 0,
                    ..PlannerConfig::default()
                },
                "nodes_per_phase",
            ),
            (
                PlannerConfig {
                    time_budget_s: Some(-1.0),
                    ..PlannerConfig::default()
                },
                "time_budget_s",
            ),
        ];
        for (config, field) in cases {
            let message = config.validate().expect_err(field).to_string();
            assert!(message.contains(field), "{message}");
        }
    }
}
