//! Planning in the closed loop: the plan in force, the graded fallback and
//! the evasive manoeuvre, what is left of a plan, and when to plan again.

use std::time::Instant;
use vorrt_colregs::{EncounterLatch, VesselState};
use vorrt_geometry::angle::signed_turn;
use vorrt_jfs::{Leg, OwnshipModel, TargetState};
use vorrt_planner::{
    Compliance, Constraint, EvasionSearch, EvasiveManeuver, Plan, PlanStatistics, Planner,
    PlannerConfig, PlannerError, PlanningProblem, SearchEffort, Waypoint, evasive_leg_holding,
    holds_manoeuvre_in_force, legs_min_distance,
};

use super::record::{PlanEvent, PlanTrigger};

/// A latched encounter is the one the plan foresaw when their reference
/// courses agree within this, radians (4°).
pub const REFERENCE_MATCH_RAD: f64 = 4.0 * std::f64::consts::PI / 180.0;

/// After a failed plan (or a fallback plan), seconds until ownship tries
/// again for a plan that keeps every rule, unless the encounters in force
/// change first. The wait doubles after each retry in a row that keeps the
/// plan in force ([`RETRY_DOUBLINGS`], decision 76).
pub const RETRY_AFTER_S: f64 = 20.0;

/// How many times the wait between retries ([`RETRY_AFTER_S`]) doubles
/// while retry after retry keeps the plan in force, so that it grows to at
/// most 160 s (decision 76). A retry that finds nothing better is a search
/// of every stricter level spent for nothing: the generated run with 100
/// targets retried 136 times in 6900 s, and 134 of them kept the plan in
/// force; with the wait doubling it takes half the time. The wait starts
/// again from [`RETRY_AFTER_S`] whenever a plan is put in force, and a
/// change of the encounters in force still asks at once.
pub const RETRY_DOUBLINGS: u32 = 3;

/// A target's predicted return to its route that moves by more than this
/// from the one the plan in force assumed asks whether that plan still
/// holds, seconds: the uncertainty its prediction allows for
/// (`vorrt_jfs::TURN_TIMING_UNCERTAINTY_S`).
pub const RETURN_MOVED_S: f64 = vorrt_jfs::TURN_TIMING_UNCERTAINTY_S;

/// A plan found when the vessels are past and clear
/// ([`PlanTrigger::PastAndClear`]) replaces the plan in force only where it
/// reaches the goal at least this much sooner, seconds; and the trigger is
/// asked only where the plan in force arrives this much later than the
/// straight line to the goal at its speed would (decision 52). One
/// observation window (`colregs::rules::STEADY_COURSE_WINDOW_S`): a smaller
/// gain is no reason to change a course an observer has seen steady.
pub const PAST_AND_CLEAR_GAIN_S: f64 = 60.0;

/// While the plan in force would reach the goal only after the run ends
/// ([`PlanTrigger::LateArrival`]), ownship asks for a sooner plan at most
/// this often, seconds (decision 63): as the vessels move on, a shorter
/// manoeuvre the search refused before may keep every rule.
pub const LATE_ARRIVAL_ASK_S: f64 = 60.0;

/// How far ahead the evasive course is judged, seconds.
pub const EVASION_HORIZON_S: f64 = 600.0;

/// How many evenly spaced courses the evasive manoeuvre chooses from (5°).
pub const EVASION_COURSES: usize = 72;

/// When ownship, sailing a fallback plan (or the evasive manoeuvre), next
/// tries for a plan that keeps every rule: [`RETRY_AFTER_S`] after the last
/// failure, doubled after each retry in a row that kept the plan in force
/// (up to [`RETRY_DOUBLINGS`] times), or at once when the encounters in
/// force change (one released, a new one latched, or a reference course
/// changed), since the situation the failure was judged in is then gone.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct RetryTimer {
    /// When the next retry is due, seconds (infinite: none pending).
    at_s: f64,
    /// Retries in a row that found no plan keeping more rules.
    kept_in_a_row: u32,
    /// The encounters in force at the last failure.
    situation: Vec<Option<EncounterLatch>>,
}

impl RetryTimer {
    /// No retry pending.
    pub(super) fn idle() -> Self {
        Self {
            at_s: f64::INFINITY,
            kept_in_a_row: 0,
            situation: Vec::new(),
        }
    }

    /// A plan that keeps every rule is in force: nothing to retry.
    fn succeeded(&mut self) {
        *self = Self::idle();
    }

    /// The search for a fully compliant plan failed at `time_s` with
    /// `encounters` in force (or a fallback plan was put in force then):
    /// the wait starts from [`RETRY_AFTER_S`].
    fn failed(&mut self, time_s: f64, encounters: &[Option<EncounterLatch>]) {
        self.kept_in_a_row = 0;
        self.wait_from(time_s, encounters);
    }

    /// A retry at `time_s` with `encounters` in force found no plan to put
    /// in force instead of the one in force: the wait doubles
    /// ([`RETRY_DOUBLINGS`]).
    pub(super) fn kept(&mut self, time_s: f64, encounters: &[Option<EncounterLatch>]) {
        self.kept_in_a_row = self.kept_in_a_row.saturating_add(1);
        self.wait_from(time_s, encounters);
    }

    /// The next retry is due after the wait for `kept_in_a_row`, from
    /// `time_s`, or when `encounters` change.
    fn wait_from(&mut self, time_s: f64, encounters: &[Option<EncounterLatch>]) {
        let doublings = self.kept_in_a_row.min(RETRY_DOUBLINGS);
        self.at_s = time_s + RETRY_AFTER_S * f64::from(1_u32 << doublings);
        self.situation.clear();
        self.situation.extend_from_slice(encounters);
    }

    /// A plan found at `compliance` was put in force at `time_s` with
    /// `encounters` in force: nothing to retry if it keeps every rule, else
    /// a fallback plan is sailed until a compliant one exists.
    fn put_in_force(
        &mut self,
        compliance: Compliance,
        time_s: f64,
        encounters: &[Option<EncounterLatch>],
    ) {
        if compliance == Compliance::Full {
            self.succeeded();
        } else {
            self.failed(time_s, encounters);
        }
    }

    /// Whether no retry is pending (a plan that keeps every rule is in
    /// force).
    pub(super) fn is_idle(&self) -> bool {
        !self.at_s.is_finite()
    }

    /// Whether a retry is due at `time_s` with `encounters` in force.
    pub(super) fn due(&self, time_s: f64, encounters: &[Option<EncounterLatch>]) -> bool {
        self.at_s.is_finite() && (time_s >= self.at_s || self.situation != encounters)
    }
}

/// The plan ownship is following, with what it assumed about the targets.
#[derive(Debug)]
pub(super) struct ActivePlan {
    pub(super) plan: Plan,
    /// The level of the graded fallback the plan keeps (the evasive
    /// manoeuvre: [`Compliance::SafetyOnly`]).
    pub(super) compliance: Compliance,
    /// When `predicted` was taken, seconds.
    pub(super) predicted_at_s: f64,
    pub(super) predicted: Vec<TargetState>,
    /// Per target, every encounter the plan expects to have with it.
    pub(super) anticipated: Vec<Vec<EncounterLatch>>,
    /// Whether an encounter has been in force at some moment since the
    /// plan was made (or since [`PlanTrigger::PastAndClear`] last asked):
    /// the plan's alteration was made, or held, for it.
    pub(super) encounters_seen: bool,
    /// Whether this is the evasive manoeuvre (judged against nothing; only
    /// the retry timer ends it).
    pub(super) evasive: bool,
    /// The evasive manoeuvre, when this is one: held again at the next
    /// failure unless another is clearly better (`evasive_leg_holding`).
    pub(super) evasion: Option<EvasiveManeuver>,
}

impl ActivePlan {
    /// The plan passed the validity check again at `time_s` with the
    /// targets now `predicted` and `latches` in force, and is kept: what it
    /// assumes is brought up to date, so the next trigger is judged against
    /// the present prediction and an encounter it was checked against is
    /// foreseen.
    pub(super) fn kept(
        &mut self,
        predicted: Vec<TargetState>,
        time_s: f64,
        latches: &[Option<EncounterLatch>],
    ) {
        self.predicted = predicted;
        self.predicted_at_s = time_s;
        self.encounters_seen |= latches.iter().any(Option::is_some);
        for (expected, latch) in self.anticipated.iter_mut().zip(latches) {
            if let Some(latch) = latch
                && !expected.contains(latch)
            {
                expected.push(*latch);
            }
        }
    }
}

/// What one planner call is for.
pub(super) struct PlanCall {
    pub(super) why: PlanTrigger,
    pub(super) seed: u64,
    pub(super) clearance_m: f64,
    /// How fast ownship changes speed, m/s² (the evasive manoeuvre's).
    pub(super) speed_change_mps2: f64,
}

/// What the searches of one planner call spent, over every level of the
/// graded fallback tried.
struct Attempts {
    /// The error of the first search that failed, if any did.
    first_error: Option<vorrt_planner::PlannerError>,
    /// The failed searches' statistics (the first one's, with the time of
    /// all).
    spent: PlanStatistics,
    /// Random samples drawn by every search.
    samples_drawn: u64,
}

/// Calls the planners on `problem`, from all the rules down the graded
/// fallback, and puts what comes of it in force: the first plan found, or on
/// failure the previous plan if the planner's validity check still accepts
/// it, or else the evasive leg (sailed with `model`). A retry searches
/// with the first phase only ([`SearchEffort::FirstPhase`]) at every level
/// but the last (safety only): it is one more draw of many while ownship
/// sails a fallback plan. A level whose search would only repeat the failed
/// search of a stricter level is not asked (`Planner::would_repeat`: no move
/// was refused for a duty it drops, so it would draw the same samples and
/// fail the same way).
pub(super) fn plan_now<C: Constraint>(
    planners: &mut [Planner<C>],
    problem: &PlanningProblem,
    model: &OwnshipModel,
    call: &PlanCall,
    active: &mut Option<ActivePlan>,
    plans: &mut Vec<PlanEvent>,
    retry: &mut RetryTimer,
) {
    let time_s = problem.start_time_s;
    let started = Instant::now();
    let (found, mut attempts) = search(planners, problem, call);
    let Some((plan, compliance)) = found else {
        retry.failed(time_s, &problem.encounters);
        if attempts.spent.elapsed_s == 0.0 {
            attempts.spent.elapsed_s = started.elapsed().as_secs_f64();
        }
        fall_back(planners, problem, model, call, active, plans, attempts);
        return;
    };
    retry.put_in_force(compliance, time_s, &problem.encounters);
    put_in_force(plan, compliance, &attempts, problem, call, active, plans);
}

/// Puts `plan`, found at `compliance` by a call that spent `attempts`, in
/// force, and records it.
fn put_in_force(
    plan: Plan,
    compliance: Compliance,
    attempts: &Attempts,
    problem: &PlanningProblem,
    call: &PlanCall,
    active: &mut Option<ActivePlan>,
    plans: &mut Vec<PlanEvent>,
) {
    let time_s = problem.start_time_s;
    let mut statistics = plan.statistics;
    statistics.elapsed_s += attempts.spent.elapsed_s;
    plans.push(PlanEvent {
        time_s,
        trigger: call.why,
        seed: call.seed,
        succeeded: true,
        error: attempts.first_error.as_ref().map(ToString::to_string),
        statistics,
        waypoints: plan.waypoints.clone(),
        speeds_mps: plan.waypoint_speeds_mps(),
        evasive_course_deg: None,
        evasive_speed_mps: None,
        compliance,
        samples_drawn: attempts.samples_drawn,
    });
    let anticipated = plan.anticipated_encounters();
    *active = Some(ActivePlan {
        plan,
        compliance,
        predicted_at_s: time_s,
        predicted: problem.targets.clone(),
        anticipated,
        encounters_seen: problem.encounters.iter().any(Option::is_some),
        evasive: false,
        evasion: None,
    });
}

/// One planner per level of the graded fallback, from all the rules down
/// (rules 2(b), 17(b)).
/// Every level keeps `constraint`: it is no duty the fallback may drop.
pub(super) fn graded_planners<C: Constraint + Clone>(
    config: &PlannerConfig,
    constraint: &C,
) -> Result<Vec<Planner<C>>, PlannerError> {
    let mut planners = Vec::new();
    let mut level = Some(config.compliance);
    while let Some(compliance) = level {
        planners.push(Planner::with_constraint(
            PlannerConfig {
                compliance,
                ..*config
            },
            constraint.clone(),
        )?);
        level = compliance.relaxed();
    }
    Ok(planners)
}

/// Where the planner of `compliance` stands in `planners` (the graded
/// fallback, strictest first), if there is one.
fn level_of<C: Constraint>(planners: &[Planner<C>], compliance: Compliance) -> Option<usize> {
    planners
        .iter()
        .position(|planner| planner.config().compliance == compliance)
}

/// The searches of one planner call, from all the rules down: the first
/// plan found with the level it keeps (`None` if every level failed), and
/// what every search spent.
fn search<C: Constraint>(
    planners: &mut [Planner<C>],
    problem: &PlanningProblem,
    call: &PlanCall,
) -> (Option<(Plan, Compliance)>, Attempts) {
    let mut attempts = Attempts {
        first_error: None,
        spent: PlanStatistics::default(),
        samples_drawn: 0,
    };
    // The last level that searched and failed (`would_repeat` knows
    // whether it found no safe path).
    let mut failed: Option<usize> = None;
    for index in 0..planners.len() {
        let compliance = planners[index].config().compliance;
        // The stricter levels grow a tree only where the user constraint
        // refused the manoeuvres from the root (decision 66), a retry's
        // only its first phase; the last level, safety alone, always
        // searches in full.
        let effort = match (compliance.relaxed(), call.why) {
            (None, _) => SearchEffort::Full,
            (Some(_), PlanTrigger::Retry) => SearchEffort::FirstPhaseWhereConstrained,
            (Some(_), _) => SearchEffort::FullWhereConstrained,
        };
        if failed.is_some_and(|failed| {
            planners[failed].would_repeat(problem, planners[index].config(), call.seed, effort)
        }) {
            continue;
        }
        // After a failed level, its verdicts that this one would repeat are
        // replayed (`Planner::plan_after`, decision 53): the same plan or
        // failure, for less work.
        let found = match failed {
            Some(failed) => {
                let (stricter, rest) = planners.split_at_mut(index);
                rest[0].plan_after(problem, call.seed, effort, &stricter[failed])
            }
            None => planners[index].plan_with(problem, call.seed, effort),
        };
        match found {
            Ok(plan) => {
                attempts.samples_drawn += plan.statistics.samples;
                return (Some((plan, compliance)), attempts);
            }
            Err(error) => {
                if let Some(statistics) = error.statistics() {
                    attempts.samples_drawn += statistics.samples;
                    attempts.spent.elapsed_s += statistics.elapsed_s;
                    if attempts.first_error.is_none() {
                        let elapsed_s = attempts.spent.elapsed_s;
                        attempts.spent = *statistics;
                        attempts.spent.elapsed_s = elapsed_s;
                    }
                }
                failed = Some(index);
                if attempts.first_error.is_none() {
                    attempts.first_error = Some(error);
                }
            }
        }
    }
    (None, attempts)
}

/// After every level failed: keeps the plan in force if the validity check
/// of its level still accepts the rest of it ([`in_force_holds`]), or else
/// puts the evasive
/// manoeuvre in force (the one in force held unless another is clearly
/// better); records the failed call. A plan in force that no longer passes
/// the check is the manoeuvre under way, and is held against the evasive
/// manoeuvre by the same judgement as an evasive one in force
/// (`holds_manoeuvre_in_force`, decision 56): replaced only by a course that
/// keeps the clearance or keeps clearly farther than the rest of the plan.
fn fall_back<C: Constraint>(
    planners: &[Planner<C>],
    problem: &PlanningProblem,
    model: &OwnshipModel,
    call: &PlanCall,
    active: &mut Option<ActivePlan>,
    plans: &mut Vec<PlanEvent>,
    attempts: Attempts,
) {
    let time_s = problem.start_time_s;
    // The rest of the plan in force, when it is a plan (not the evasive leg).
    let in_force = active
        .as_ref()
        .filter(|active| !active.evasive)
        .map(|active| remaining_legs(&active.plan, time_s));
    // Judged at its own level, as at any trigger (decision 64).
    let kept_level = active
        .as_ref()
        .filter(|active| !active.evasive && in_force_holds(planners, problem, active))
        .map(|active| active.compliance);
    let keep_plan = kept_level.is_some();
    let mut held_plan = false;
    let evasion = if keep_plan {
        None
    } else {
        let holding = active.as_ref().and_then(|active| active.evasion);
        let search = EvasionSearch {
            horizon_s: EVASION_HORIZON_S,
            courses: EVASION_COURSES,
            clearance_m: call.clearance_m,
            model,
            speed_change_mps2: call.speed_change_mps2,
        };
        // The planner's own evasive manoeuvre: it keeps its constraint too.
        let (leg, evasion) = match planners.first() {
            Some(planner) => planner.evasive_leg(problem, &search, holding),
            None => evasive_leg_holding(
                problem,
                search.horizon_s,
                search.courses,
                search.clearance_m,
                model,
                search.speed_change_mps2,
                holding,
            ),
        };
        held_plan = in_force.as_ref().is_some_and(|legs| {
            let held_m = legs_min_distance(problem, legs, EVASION_HORIZON_S);
            holds_manoeuvre_in_force(held_m, evasion.min_distance_m, call.clearance_m)
        });
        if held_plan {
            None
        } else {
            *active = Some(ActivePlan {
                plan: leg_plan(leg, time_s),
                compliance: Compliance::SafetyOnly,
                predicted_at_s: time_s,
                predicted: problem.targets.clone(),
                anticipated: vec![Vec::new(); problem.targets.len()],
                encounters_seen: false,
                evasive: true,
                evasion: Some(evasion),
            });
            Some(evasion)
        }
    };
    plans.push(PlanEvent {
        time_s,
        trigger: call.why,
        seed: call.seed,
        succeeded: false,
        error: attempts.first_error.map(|error| error.to_string()),
        statistics: attempts.spent,
        waypoints: Vec::new(),
        speeds_mps: Vec::new(),
        evasive_course_deg: evasion.map(|evasion| evasion.course_rad.to_degrees()),
        evasive_speed_mps: evasion.map(|evasion| evasion.speed_mps),
        samples_drawn: attempts.samples_drawn,
        // The level of the plan kept (a fallback plan kept departs from
        // the rules as it did), else the evasive manoeuvre's.
        compliance: kept_level.unwrap_or(Compliance::SafetyOnly),
    });
    if held_plan && let Some(active) = active.as_mut() {
        // Held, not re-checked: what it assumes is brought up to date, so
        // the next trigger is judged against the present prediction.
        active.kept(problem.targets.clone(), time_s, &problem.encounters);
    }
}

/// A plan of one leg starting at `time_s` (the evasive manoeuvre).
pub(super) fn leg_plan(leg: Leg, time_s: f64) -> Plan {
    Plan {
        waypoints: vec![
            Waypoint {
                position_m: leg.start_m,
                time_s,
                course_rad: leg.start_course_rad,
            },
            Waypoint {
                position_m: leg.end_m(),
                time_s: time_s + leg.duration_s(),
                course_rad: leg.course_rad,
            },
        ],
        legs: vec![leg],
        target_states: Vec::new(),
        encounters: Vec::new(),
        statistics: PlanStatistics::default(),
    }
}

/// The legs of `plan` still to sail from `time_s` on, the one under way cut
/// at ownship's present pose.
pub(super) fn remaining_legs(plan: &Plan, time_s: f64) -> Vec<Leg> {
    let mut legs = Vec::new();
    for (index, leg) in plan.legs.iter().enumerate() {
        let (start_s, end_s) = (
            plan.waypoints[index].time_s,
            plan.waypoints[index + 1].time_s,
        );
        if end_s <= time_s {
            continue;
        }
        if start_s < time_s {
            legs.push(leg.remainder(time_s - start_s));
        } else {
            legs.push(*leg);
        }
    }
    legs
}

/// Ownship's state at `time_s` along `plan` (at its end once the plan
/// ends): its pose and its speed along the plan's speed profile.
pub(super) fn follow(plan: &Plan, own: &VesselState, time_s: f64) -> VesselState {
    match plan.pose_at(time_s) {
        Some(pose) => VesselState {
            position_m: pose.position_m,
            course_rad: pose.course_rad,
            speed_mps: plan.speed_at(time_s).unwrap_or(own.speed_mps),
            ..*own
        },
        None => own.advanced(0.0),
    }
}

/// Whether the plan in force has stopped being valid, and why, with the
/// targets truly at `targets` and predicted as `predicted_now`.
pub(super) fn replan_trigger(
    active: Option<&ActivePlan>,
    targets: &[VesselState],
    predicted_now: &[TargetState],
    latches: &[Option<EncounterLatch>],
    time_s: f64,
    deviation_m: f64,
) -> Option<PlanTrigger> {
    let active = active.filter(|active| !active.evasive)?;
    let elapsed_s = time_s - active.predicted_at_s;
    for (index, (target, predicted)) in targets.iter().zip(&active.predicted).enumerate() {
        let expected = predicted.predict(elapsed_s).vessel.position_m;
        if expected.distance(target.position_m) > deviation_m {
            return Some(PlanTrigger::TargetOffPrediction { target: index });
        }
    }
    // A return to its route foreseen now that the plan did not assume (or
    // at another time): the target is where it was predicted, but not
    // where it is now predicted to go.
    for (index, (now, planned)) in predicted_now.iter().zip(&active.predicted).enumerate() {
        if planned.holds_course_for_s.is_none() && now.holds_course_for_s.is_none() {
            // No return foreseen, then or now (nearly every target).
            continue;
        }
        let assumed = planned.predict(elapsed_s).holds_course_for_s;
        if return_moved(assumed, now.holds_course_for_s) {
            return Some(PlanTrigger::PredictionChanged { target: index });
        }
    }
    for (index, latch) in latches.iter().enumerate() {
        // Foreseen: the plan latched the same type against (nearly) the same
        // reference course, so its COLREGs checks are the ones in force.
        let foreseen = |actual: &EncounterLatch| {
            active.anticipated.get(index).is_none_or(|expected| {
                expected.iter().any(|planned| {
                    planned.encounter == actual.encounter
                        && signed_turn(planned.reference_course_rad, actual.reference_course_rad)
                            .abs()
                            <= REFERENCE_MATCH_RAD
                })
            })
        };
        if let Some(latch) = latch
            && !foreseen(latch)
        {
            return Some(PlanTrigger::NewEncounter { target: index });
        }
    }
    None
}

/// Whether a target's return to its route, `assumed_s` from now by the plan
/// in force and `now_s` by the present prediction (`None`: no return
/// foreseen), differs enough to ask whether the plan still holds.
fn return_moved(assumed_s: Option<f64>, now_s: Option<f64>) -> bool {
    match (assumed_s, now_s) {
        (None, None) => false,
        (Some(assumed_s), Some(now_s)) => (assumed_s - now_s).abs() > RETURN_MOVED_S,
        _ => true,
    }
}

mod retry;
mod sooner;
pub(super) use retry::{in_force_holds, retry_in_force};
pub(super) use sooner::{Asked, arrival_s, late_arrival_due, past_and_clear_due, plan_if_sooner};
#[cfg(test)]
mod tests;
