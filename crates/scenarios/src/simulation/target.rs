//! The targets as the closed loop moves them, and how ownship predicts them
//! (from what they announce and are seen doing): the [`TargetMotion`] seam,
//! and the scenario's behaviours behind it ([`BehaviourTarget`]).

use crate::scenario::{Behaviour, COLREGS_TURN_DEG, NOISE_TIME_CONSTANT_S};
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use vorrt_colregs::observed::TrackObservation;
use vorrt_colregs::{
    Encounter, EncounterLatch, Role, RuleParameters, VesselState, has_passed, update_latch,
};
use vorrt_geometry::angle::signed_turn;
use vorrt_geometry::{angle, units};
use vorrt_jfs::TargetState;

/// The longest a [`Behaviour::Colregs`] target holds its alteration after
/// its encounter with ownship was released, seconds, while its return
/// would bring risk back (`BehaviourTarget::resumes`, decision 43).
pub(super) const RESUME_AFTER_S: f64 = 30.0;

/// A target that is seen this far off the course to its announced
/// destination is predicted on the course it is seen on, radians (10°, twice
/// the course noise of a `noisy` target).
pub const OBSERVED_TURN_RAD: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// How one target moves in the closed loop, and how ownship predicts it: the
/// one seam every target behaviour is behind (the scenario's
/// [`Behaviour`]s, a recorded track: [`RecordedMotion`](super::RecordedMotion)).
///
/// A motion starts at the closed loop's time 0. The loop asks for the
/// target's true state at every step ([`vessel`](Self::vessel)), moves it
/// one step at a time ([`advance`](Self::advance)), and gives ownship's
/// planner only [`announced`](Self::announced): a prediction made from what
/// the target shows at present, as ownship's watch would make it. A motion
/// is `Send`, so a run can move to another thread (a batch worker, a
/// binding).
pub trait TargetMotion: std::fmt::Debug + Send {
    /// The target's true state at present.
    fn vessel(&self) -> VesselState;

    /// Moves the target from `time_s` to `next_time_s` on the loop's clock;
    /// `own` is ownship at `time_s` (a target that reacts to ownship sees it
    /// there), `rules` the run's rule constants.
    fn advance(&mut self, time_s: f64, next_time_s: f64, own: &VesselState, rules: &RuleParameters);

    /// How ownship (`own`, with `encounter` latched against this target, if
    /// any) predicts the target now. Only what the target shows at present
    /// may go into it (its state seen by AIS and radar, the course, speed
    /// and destination it broadcasts), never where it will truly be: that is
    /// what ownship's planner is given.
    fn announced(
        &self,
        own: &VesselState,
        encounter: Option<Encounter>,
        rules: &RuleParameters,
    ) -> TargetState;

    /// How the target's track is observed in the run's record: exact
    /// positions for a simulated motion (the default); a recorded track's
    /// fixes carry the jitter of the recording, estimated from its
    /// positions.
    fn observation(&self) -> TrackObservation {
        TrackObservation::exact()
    }
}

/// A scenario's target, moved by its [`Behaviour`].
#[derive(Debug, Clone)]
pub(super) struct BehaviourTarget {
    /// Where it is now; `goal_m` is the goal it steers for (`None` once a
    /// [`Behaviour::SuddenTurn`] target has turned, or without a goal).
    state: TargetState,
    behaviour: Behaviour,
    /// The speed it announces and returns to, m/s.
    nominal_speed_mps: f64,
    /// The course it holds when it has no goal, radians.
    nominal_course_rad: f64,
    /// The noise stream of a [`Behaviour::Noisy`] target.
    noise: Option<ChaCha8Rng>,
    course_offset_rad: f64,
    speed_offset_mps: f64,
    /// A [`Behaviour::Colregs`] target's encounter with ownship, from its side.
    latch: Option<EncounterLatch>,
    /// The course a giving-way [`Behaviour::Colregs`] target holds.
    avoiding_course_rad: Option<f64>,
    /// When that target's encounter was released while it still holds its
    /// alteration, seconds (`resumes`).
    released_at_s: Option<f64>,
    /// Whether a [`Behaviour::SuddenTurn`] target has turned.
    turned: bool,
}

/// The seed of target `index`'s noise stream in a run seeded with `seed`.
fn noise_stream(seed: u64, index: usize) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x6E6F_6973_795F_7467);
    rng.set_stream(index as u64);
    rng
}

/// A standard normal draw (Box-Muller) from `rng`.
fn standard_normal(rng: &mut ChaCha8Rng) -> f64 {
    // 53 random bits in (0, 1].
    #[expect(clippy::cast_precision_loss, reason = "53-bit values, exact in f64")]
    let unit = |rng: &mut ChaCha8Rng| ((rng.next_u64() >> 11) as f64 + 1.0) / (1u64 << 53) as f64;
    let (u1, u2) = (unit(rng), unit(rng));
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

impl BehaviourTarget {
    /// Target `index` of a run seeded with `seed`, as `spec` describes it.
    pub(super) fn new(spec: &crate::VesselSpec, index: usize, seed: u64) -> Self {
        let state = match spec.behaviour {
            Behaviour::ConstantVelocity => TargetState::constant_velocity(spec.state()),
            _ => spec.target_state(),
        };
        let noise =
            matches!(spec.behaviour, Behaviour::Noisy { .. }).then(|| noise_stream(seed, index));
        Self {
            state,
            behaviour: spec.behaviour,
            nominal_speed_mps: spec.speed_mps(),
            nominal_course_rad: state.vessel.course_rad,
            noise,
            course_offset_rad: 0.0,
            speed_offset_mps: 0.0,
            latch: None,
            avoiding_course_rad: None,
            released_at_s: None,
            turned: false,
        }
    }

    /// The course the target would steer undisturbed: for its goal, or its
    /// nominal course without one.
    fn intended_course_rad(&self) -> f64 {
        match self.state.goal_m {
            Some(goal) if goal != self.state.vessel.position_m => {
                angle::unit_to_course(goal - self.state.vessel.position_m)
            }
            Some(_) => self.state.vessel.course_rad,
            None => self.nominal_course_rad,
        }
    }

    /// Whether a [`Behaviour::Colregs`] target whose encounter with ownship
    /// (`own`) was released `held_s` ago resumes its route at `time_s`: once
    /// steering for it again latches no encounter with ownship at once, or
    /// after [`RESUME_AFTER_S`] in any case. Its give-way turn opens the
    /// range, which releases the latch (`has_passed`), and its return closed
    /// it again: resumed at once, it turned back and forth at every step,
    /// which rule 8(b) forbids and rule 8(d) ("until the other vessel is
    /// finally past and clear") does not allow (decision 43). So it holds
    /// its alteration while its return would bring risk of collision back,
    /// as ownship's own return is checked (decision 28); the bound keeps two
    /// vessels from holding each other off their routes for ever.
    fn resumes(&self, own: &VesselState, held_s: f64, time_s: f64, rules: &RuleParameters) -> bool {
        if held_s >= RESUME_AFTER_S {
            return true;
        }
        let resumed = VesselState {
            course_rad: self.intended_course_rad(),
            speed_mps: self.nominal_speed_mps,
            ..self.state.vessel
        };
        update_latch(None, &resumed, own, time_s, rules).is_none()
    }

    /// Sails `duration_s` at `course_rad` and `speed_mps`, stopping on the
    /// goal if it comes within reach.
    fn steer(&mut self, course_rad: f64, speed_mps: f64, duration_s: f64) {
        let vessel = &mut self.state.vessel;
        if self.state.goal_m == Some(vessel.position_m) {
            vessel.speed_mps = 0.0;
            return;
        }
        vessel.course_rad = angle::normalize_2pi(course_rad);
        vessel.speed_mps = speed_mps;
        let travel_m = speed_mps * duration_s;
        match self.state.goal_m {
            Some(goal) if vessel.position_m.distance(goal) <= travel_m => {
                vessel.position_m = goal;
                vessel.speed_mps = 0.0;
            }
            _ => vessel.position_m += angle::velocity(vessel.course_rad, speed_mps) * duration_s,
        }
    }
}

impl TargetMotion for BehaviourTarget {
    fn vessel(&self) -> VesselState {
        self.state.vessel
    }

    fn advance(
        &mut self,
        time_s: f64,
        next_time_s: f64,
        own: &VesselState,
        rules: &RuleParameters,
    ) {
        let duration_s = next_time_s - time_s;
        match self.behaviour {
            Behaviour::SuddenTurn { at_s, turn_deg } => {
                if !self.turned && time_s + duration_s >= at_s {
                    let before_s = (at_s - time_s).max(0.0);
                    self.state = self.state.predict(before_s);
                    let mut vessel = self.state.vessel;
                    vessel.course_rad =
                        angle::normalize_2pi(vessel.course_rad + turn_deg.to_radians());
                    self.state = TargetState::constant_velocity(vessel);
                    self.turned = true;
                    self.state = self.state.predict(duration_s - before_s);
                } else {
                    self.state = self.state.predict(duration_s);
                }
            }
            Behaviour::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            } => {
                if let Some(rng) = self.noise.as_mut() {
                    let decay = (-duration_s / NOISE_TIME_CONSTANT_S).exp();
                    let spread = (1.0 - decay * decay).max(0.0).sqrt();
                    let course_sigma = course_sigma_deg.to_radians();
                    let speed_sigma = units::knots_to_mps(speed_sigma_kn);
                    self.course_offset_rad = decay * self.course_offset_rad
                        + course_sigma * spread * standard_normal(rng);
                    self.speed_offset_mps =
                        decay * self.speed_offset_mps + speed_sigma * spread * standard_normal(rng);
                }
                let course = self.intended_course_rad() + self.course_offset_rad;
                let speed = (self.nominal_speed_mps + self.speed_offset_mps).max(0.0);
                self.steer(course, speed, duration_s);
            }
            Behaviour::Colregs => {
                self.latch = update_latch(self.latch, &self.state.vessel, own, time_s, rules);
                match self.latch {
                    Some(latch) if latch.encounter.role() == Role::GiveWay => {
                        self.released_at_s = None;
                        if self.avoiding_course_rad.is_none() {
                            self.avoiding_course_rad = Some(angle::normalize_2pi(
                                latch.reference_course_rad + COLREGS_TURN_DEG.to_radians(),
                            ));
                        }
                    }
                    Some(_) => {
                        self.avoiding_course_rad = None;
                        self.released_at_s = None;
                    }
                    // Released: back to the route, unless its return would
                    // latch an encounter with ownship again at once: then it
                    // holds its alteration, for a bounded time (`resumes`,
                    // rule 8(d), decision 43).
                    None => {
                        if self.avoiding_course_rad.is_some() {
                            let released_at_s = *self.released_at_s.get_or_insert(time_s);
                            if self.resumes(own, time_s - released_at_s, time_s, rules) {
                                self.avoiding_course_rad = None;
                                self.released_at_s = None;
                            }
                        }
                    }
                }
                let course = self
                    .avoiding_course_rad
                    .unwrap_or_else(|| self.intended_course_rad());
                self.steer(course, self.nominal_speed_mps, duration_s);
            }
            _ => self.state = self.state.predict(duration_s),
        }
    }

    /// How ownship (`own`, with `encounter` latched against this target, if
    /// any) predicts the target: from what it broadcasts (AIS: course, speed,
    /// destination) and what it is seen doing. A goal-bound target is
    /// predicted steering for its goal at its nominal speed, unless it is
    /// seen more than [`OBSERVED_TURN_RAD`] off that course: then it is
    /// predicted holding the course it is on until it has passed ownship
    /// ([`passing_time_s`]), and then steering for its goal again. Any
    /// other target holds its course at its nominal speed (its present
    /// course and speed for the constant-motion behaviours).
    fn announced(
        &self,
        own: &VesselState,
        encounter: Option<Encounter>,
        rules: &RuleParameters,
    ) -> TargetState {
        let vessel = self.state.vessel;
        match self.behaviour {
            Behaviour::ConstantToGoal | Behaviour::ConstantVelocity => match self.state.goal_m {
                Some(goal) => TargetState {
                    vessel,
                    goal_m: Some(goal),
                    holds_course_for_s: None,
                },
                None => TargetState::constant_velocity(vessel),
            },
            _ => match self.state.goal_m {
                // A turn seen over ground updates the prediction: a target
                // well off the course to its destination is predicted to hold
                // the course it is seen on (it is giving way, or has changed
                // its mind), as AIS and radar show it, until it is past
                // ownship (rule 8(d)), and then to return to its route.
                Some(goal)
                    if !self.state.has_arrived()
                        && signed_turn(
                            angle::unit_to_course(goal - vessel.position_m),
                            vessel.course_rad,
                        )
                        .abs()
                            > OBSERVED_TURN_RAD =>
                {
                    let seen = VesselState {
                        speed_mps: self.nominal_speed_mps,
                        ..vessel
                    };
                    let returns_after_s = (encounter == Some(Encounter::BeingOvertaken))
                        .then(|| passing_time_s(own, &seen, Encounter::BeingOvertaken, rules))
                        .flatten();
                    match returns_after_s {
                        Some(hold_s) => {
                            TargetState::holding_course_then_toward_goal(seen, goal, hold_s)
                        }
                        None => TargetState::constant_velocity(seen),
                    }
                }
                Some(goal) => {
                    let speed_mps = if self.state.has_arrived() {
                        0.0
                    } else {
                        self.nominal_speed_mps
                    };
                    TargetState::toward_goal(
                        VesselState {
                            speed_mps,
                            ..vessel
                        },
                        goal,
                    )
                }
                None if self.turned => TargetState::constant_velocity(vessel),
                None => TargetState::constant_velocity(VesselState {
                    course_rad: self.nominal_course_rad,
                    speed_mps: self.nominal_speed_mps,
                    ..vessel
                }),
            },
        }
    }
}

/// How far ahead a target off its route is followed to the moment it has
/// passed ownship, seconds (beyond it, it is predicted on its course for ever).
const PASSING_HORIZON_S: f64 = 300.0;

/// The step of that search, seconds.
const PASSING_STEP_S: f64 = 5.0;

/// Seconds until `target` has passed `own`, both holding their course and
/// speed: as the rules judge passing ([`has_passed`], with the `encounter`
/// between them), and, in an overtaking,
/// with the overtaking vessel forward of the other's beam — the moment a
/// vessel that holds its alteration "until the other vessel is finally past
/// and clear" (rule 8(d)) is free to return to its route. `None` when they
/// have not passed within [`PASSING_HORIZON_S`] (an overtaking vessel that
/// falls back on its avoiding course never gets past).
fn passing_time_s(
    own: &VesselState,
    target: &VesselState,
    encounter: Encounter,
    rules: &RuleParameters,
) -> Option<f64> {
    // Whether `ahead` is forward of `astern`'s beam.
    let forward_of_beam = |ahead: &VesselState, astern: &VesselState| {
        (ahead.position_m - astern.position_m).dot(astern.velocity_mps()) > 0.0
    };
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a ratio of two positive constants, 60"
    )]
    let steps = (PASSING_HORIZON_S / PASSING_STEP_S) as u32;
    (0..=steps)
        .map(|step| f64::from(step) * PASSING_STEP_S)
        .find(|&elapsed_s| {
            let (own, target) = (own.advanced(elapsed_s), target.advanced(elapsed_s));
            let overtaken = match encounter {
                Encounter::BeingOvertaken => forward_of_beam(&target, &own),
                Encounter::Overtaking => forward_of_beam(&own, &target),
                _ => true,
            };
            overtaken && has_passed(&own, &target, encounter, rules)
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use vorrt_geometry::DVec2;

    fn vessel(x_m: f64, y_m: f64, course_deg: f64, speed_mps: f64) -> VesselState {
        VesselState::new(
            DVec2::new(x_m, y_m),
            course_deg.to_radians(),
            speed_mps,
            100.0,
        )
    }

    #[test]
    fn a_vessel_that_gives_way_does_not_turn_back_at_every_step() {
        let rules = RuleParameters::default();
        // Ownship north at 5 m/s; a COLREGs-obeying vessel 2500 m astern
        // overtakes at 6 m/s for a goal far north. Its 35° turn opens the
        // range at once (released: opening beyond `risk_cpa_m`), and its
        // return would close it again: resumed at once, it turned back and
        // forth at every step (decision 43).
        let mut own = vessel(0.0, 0.0, 0.0, 5.0);
        let mut target = BehaviourTarget {
            state: TargetState::toward_goal(
                vessel(0.0, -2500.0, 0.0, 6.0),
                DVec2::new(0.0, 50_000.0),
            ),
            behaviour: Behaviour::Colregs,
            nominal_speed_mps: 6.0,
            nominal_course_rad: 0.0,
            noise: None,
            course_offset_rad: 0.0,
            speed_offset_mps: 0.0,
            latch: None,
            avoiding_course_rad: None,
            released_at_s: None,
            turned: false,
        };
        let step_s = 5.0;
        let (mut turned_away_s, mut returns) = (None, Vec::new());
        for step in 0..120 {
            let time_s = f64::from(step) * step_s;
            let was_avoiding = target.avoiding_course_rad.is_some();
            target.advance(time_s, time_s + step_s, &own, &rules);
            own = own.advanced(step_s);
            match (was_avoiding, target.avoiding_course_rad.is_some()) {
                (false, true) => turned_away_s = Some(time_s),
                (true, false) => returns.push(time_s - turned_away_s.expect("turned first")),
                _ => {}
            }
        }
        assert!(turned_away_s.is_some(), "it gives way");
        // Every return comes after the alteration was held for the bound at
        // least (the old target returned the step after it turned).
        assert!(
            !returns.is_empty(),
            "it returns while its route is still at risk only after the bound"
        );
        assert!(
            returns.iter().all(|&held_s| held_s >= RESUME_AFTER_S),
            "{returns:?}"
        );
    }

    #[test]
    fn an_overtaking_vessel_has_passed_once_forward_of_the_beam_and_clear() {
        let rules = RuleParameters::default();
        // Ownship north at 5 m/s; a vessel 500 m astern, 300 m to starboard,
        // 10 m/s on nearly the same course: it comes up, passes and draws
        // ahead (abeam after about 100 s).
        let own = vessel(0.0, 0.0, 0.0, 5.0);
        let overtaking = vessel(300.0, -500.0, 5.0, 10.0);
        let passed_s = passing_time_s(&own, &overtaking, Encounter::BeingOvertaken, &rules)
            .expect("passes within the horizon");
        let (own_then, target_then) = (own.advanced(passed_s), overtaking.advanced(passed_s));
        assert!(
            target_then.position_m.y > own_then.position_m.y,
            "forward of the beam"
        );
        assert!(has_passed(
            &own_then,
            &target_then,
            Encounter::BeingOvertaken,
            &rules
        ));
        assert!((90.0..=PASSING_HORIZON_S).contains(&passed_s), "{passed_s}");
        // Turned away so far that it falls back: the range opens, yet it
        // never gets past, and it is predicted on its course for ever.
        let falling_back = vessel(300.0, -500.0, 70.0, 10.0);
        assert_eq!(
            passing_time_s(&own, &falling_back, Encounter::BeingOvertaken, &rules),
            None
        );
    }
}
