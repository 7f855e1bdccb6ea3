//! The rules a scenario must keep (run by every loader).

use crate::error::ScenarioError;
use crate::planner_settings::describe_config_error;
use crate::scenario::{Behaviour, Lane, Scenario, VesselSpec};
use vorrt_colregs::rules;
use vorrt_planner::error::Readable;
use vorrt_planner::{PlannerConfig, Turning};

/// The most targets one scenario may hold.
pub const MAX_TARGETS: usize = 256;
/// Positions, goals and lane ends must lie within this distance of the origin,
/// nautical miles: keeps every distance and time the planner computes finite.
pub const MAX_EXTENT_NM: f64 = 10_000.0;
/// The fastest vessel a scenario may hold, knots.
pub const MAX_SPEED_KN: f64 = 100.0;
/// The longest vessel a scenario may hold, metres.
pub const MAX_LENGTH_M: f64 = 1_000.0;
/// The longest name (of the scenario, a vessel or a lane), in characters:
/// names go into tables, plots and file names.
pub const MAX_NAME_CHARS: usize = 200;
/// The longest description, in characters.
pub const MAX_DESCRIPTION_CHARS: usize = 10_000;
/// The most steps `d'` (`planner.step_m`) ownship's straight route may take:
/// keeps one plan within seconds (the planner's budgets follow the route
/// length, see `PlannerConfig::for_route`).
pub const MAX_ROUTE_STEPS: f64 = 10_000.0;
/// The most simulation steps (`max_duration_s / time_step_s`) a scenario may
/// ask for.
pub const MAX_SIMULATION_STEPS: f64 = 10_000_000.0;

/// Which vessel of a scenario, for error messages.
#[derive(Clone, Copy)]
enum Who<'a> {
    Ownship,
    Target(usize, &'a str),
}

impl Who<'_> {
    fn field(self, field: &str) -> String {
        format!("{}.{field}", self.vessel())
    }

    fn vessel(self) -> String {
        match self {
            Who::Ownship => "ownship".to_owned(),
            Who::Target(index, name) => format!("targets[{index}] {name:?}"),
        }
    }
}

/// The start field a vessel uses.
pub(crate) fn start_field(vessel: &VesselSpec) -> &'static str {
    if vessel.start_nm.is_some() {
        "start_nm"
    } else if vessel.start_m.is_some() {
        "start_m"
    } else {
        "start_lat_lon"
    }
}

/// A name is not blank and at most [`MAX_NAME_CHARS`] long.
fn check_name(name: &str) -> Result<(), String> {
    if name.trim().is_empty() {
        return Err("must not be empty".into());
    }
    let chars = name.chars().count();
    if chars > MAX_NAME_CHARS {
        return Err(format!(
            "holds {chars} characters, more than the {MAX_NAME_CHARS} allowed"
        ));
    }
    Ok(())
}

impl Scenario {
    /// Checks every rule of the format (see `docs/scenario-format.md`,
    /// "Validation") and normalises every course into `[0, 360)` degrees.
    /// The loaders call this; call it after building or editing a scenario
    /// in code. Errors name [`Scenario::source`] as the file.
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`] naming the first field that breaks a rule.
    pub fn validate(&mut self) -> Result<(), ScenarioError> {
        let file = self.source.clone();
        let invalid = |field: String, problem: String| ScenarioError::Invalid {
            file: file.clone(),
            field,
            problem,
        };
        check_name(&self.name).map_err(|problem| invalid("name".into(), problem))?;
        if let Some(description) = &self.description {
            let chars = description.chars().count();
            if chars > MAX_DESCRIPTION_CHARS {
                return Err(invalid(
                    "description".into(),
                    format!(
                        "holds {chars} characters, more than the {MAX_DESCRIPTION_CHARS} allowed"
                    ),
                ));
            }
        }
        self.check_geographic().map_err(|(f, p)| invalid(f, p))?;
        crate::area::check_areas(self).map_err(|(f, p)| invalid(f, p))?;
        check_vessel(&mut self.ownship, Who::Ownship).map_err(|(f, p)| invalid(f, p))?;
        if self.targets.len() > MAX_TARGETS {
            return Err(invalid(
                "targets".into(),
                format!(
                    "holds {} vessels, more than the {MAX_TARGETS} allowed",
                    self.targets.len()
                ),
            ));
        }
        for (index, target) in self.targets.iter_mut().enumerate() {
            let name = target.name.clone();
            check_vessel(target, Who::Target(index, &name)).map_err(|(f, p)| invalid(f, p))?;
        }
        check_ownship(&self.ownship).map_err(|(f, p)| invalid(f, p))?;
        self.check_names().map_err(|(f, p)| invalid(f, p))?;
        let config = self
            .checked_planner_config()
            .map_err(|(f, p)| invalid(f, p))?;
        self.check_route(&config).map_err(|(f, p)| invalid(f, p))?;
        self.check_clearance(&config)
            .map_err(|(f, p)| invalid(f, p))?;
        self.check_goal_clear(&config)
            .map_err(|(f, p)| invalid(f, p))?;
        // Long ships can touch beyond the clearance.
        self.check_hulls_apart().map_err(|(f, p)| invalid(f, p))?;
        self.check_simulation().map_err(|(f, p)| invalid(f, p))?;
        // The scheme last: its lanes and zones are projected with the frame
        // the vessels were (decision 30).
        let frame = self.local_frame();
        crate::scheme::check_scheme(self, frame.as_ref()).map_err(|(f, p)| invalid(f, p))?;
        for (index, lane) in self.lanes.iter().enumerate() {
            check_lane(index, lane).map_err(|(f, p)| invalid(f, p))?;
        }
        crate::chart::check_off_land(self).map_err(|(f, p)| invalid(f, p))?;
        self.check_recorded_field()
            .map_err(|(f, p)| invalid(f, p))?;
        Ok(())
    }

    /// A `Recorded` target needs a tracks file, and a tracks file needs a
    /// name (decision 40).
    fn check_recorded_field(&self) -> Result<(), (String, String)> {
        if self
            .recorded_tracks
            .as_deref()
            .is_some_and(|path| path.trim().is_empty())
        {
            return Err((
                "recorded_tracks".into(),
                "is empty: expected the path of a tracks CSV, relative to the scenario file".into(),
            ));
        }
        if self.recorded_tracks.is_none()
            && let Some((index, target)) = self
                .targets
                .iter()
                .enumerate()
                .find(|(_, target)| target.behaviour == Behaviour::Recorded)
        {
            return Err((
                format!("targets[{index}] {:?}.behaviour", target.name),
                "is Recorded, but the scenario names no recorded_tracks file for it to follow"
                    .into(),
            ));
        }
        Ok(())
    }

    /// Checks that every [`Behaviour::Recorded`] target has a track in
    /// [`Scenario::recorded`] ([`Scenario::load`] calls it once it has read
    /// them; [`ClosedLoop`](crate::ClosedLoop) refuses a run without one).
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`] naming the target's `behaviour` field and
    /// the tracks file.
    pub fn check_recorded(&self) -> Result<(), ScenarioError> {
        for (index, target) in self.targets.iter().enumerate() {
            if target.behaviour == Behaviour::Recorded
                && self
                    .recorded
                    .track(&target.name)
                    .is_none_or(<[_]>::is_empty)
            {
                let file = if self.recorded.file.is_empty() {
                    "(no recorded tracks loaded: Scenario::load reads them)".to_owned()
                } else {
                    self.recorded.file.clone()
                };
                return Err(ScenarioError::Invalid {
                    file: self.source.clone(),
                    field: format!("targets[{index}] {:?}.behaviour", target.name),
                    problem: format!(
                        "is Recorded, but {file} has no rows with vessel {:?}",
                        target.name
                    ),
                });
            }
        }
        Ok(())
    }

    /// The length of the vessel named `name` (ownship or a target), metres.
    #[must_use]
    pub fn vessel_length_m(&self, name: &str) -> Option<f64> {
        std::iter::once(&self.ownship)
            .chain(&self.targets)
            .find(|vessel| vessel.name == name)
            .map(|vessel| vessel.length_m)
    }

    /// The planner configuration: [`PlannerConfig::default()`] with the
    /// `planner` section's fields applied, converted to SI and validated.
    ///
    /// # Errors
    /// [`ScenarioError::Invalid`] naming [`Scenario::source`] and the
    /// `planner.<field>` at fault, with its value in the file's units.
    pub fn planner_config(&self) -> Result<PlannerConfig, ScenarioError> {
        self.checked_planner_config()
            .map_err(|(field, problem)| ScenarioError::Invalid {
                file: self.source.clone(),
                field,
                problem,
            })
    }

    fn checked_planner_config(&self) -> Result<PlannerConfig, (String, String)> {
        for (name, value) in self.planner.set_numbers() {
            if !value.is_finite() {
                return Err((
                    format!("planner.{name}"),
                    format!("is {}, not a finite number", Readable(value)),
                ));
            }
        }
        let mut config = self.planner.apply_to(PlannerConfig::default());
        if let Some(rate) = self.ownship.max_turn_rate_deg_s
            && config.turning != Turning::Instant
        {
            config.turning = Turning::MaxRate {
                max_turn_rate_rad_s: rate.to_radians(),
            };
        }
        config
            .validate()
            .map_err(|error| describe_config_error(&error))?;
        Ok(config)
    }

    fn check_names(&self) -> Result<(), (String, String)> {
        for (index, target) in self.targets.iter().enumerate() {
            let who = Who::Target(index, &target.name);
            if target.name == self.ownship.name {
                return Err((
                    who.field("name"),
                    "is the name of ownship: vessel names must be unique".into(),
                ));
            }
            if let Some(first) = self.targets[..index]
                .iter()
                .position(|other| other.name == target.name)
            {
                return Err((
                    who.field("name"),
                    format!("is also the name of targets[{first}]: vessel names must be unique"),
                ));
            }
        }
        Ok(())
    }

    /// No target starts in hull contact with ownship: closer than half the
    /// sum of their lengths (`vorrt_colregs::rules::in_contact`, the one
    /// definition of collision). Evaluation judges ownship against each
    /// target, so only those pairs count; targets may pass through each
    /// other, as generated traffic does.
    fn check_hulls_apart(&self) -> Result<(), (String, String)> {
        let own = self.ownship.start_position_m();
        for (index, target) in self.targets.iter().enumerate() {
            let range = own.distance(target.start_position_m());
            let (own_length_m, length_m) = (self.ownship.length_m, target.length_m);
            if rules::in_contact(range, own_length_m, length_m) {
                let contact = rules::contact_range_m(own_length_m, length_m);
                return Err((
                    Who::Target(index, &target.name).field(start_field(target)),
                    format!(
                        "is {range:.1} m from ownship {:?} at the start, less than half the sum of their lengths ({contact:.1} m): the two start in collision",
                        self.ownship.name
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Ownship's straight route takes at most [`MAX_ROUTE_STEPS`] steps.
    fn check_route(&self, config: &PlannerConfig) -> Result<(), (String, String)> {
        let Some(goal) = self.ownship.goal_position_m() else {
            return Ok(());
        };
        let route_m = goal.distance(self.ownship.start_position_m());
        let steps = route_m / config.step_m;
        if steps > MAX_ROUTE_STEPS {
            let field = if self.ownship.goal_nm.is_some() {
                "goal_nm"
            } else {
                "goal_m"
            };
            return Err((
                Who::Ownship.field(field),
                format!(
                    "is {} nm from ownship's start: {} steps of planner.step_m = {} m, more than the {MAX_ROUTE_STEPS} a plan may take (split the route, or raise planner.step_m)",
                    Readable(route_m / vorrt_geometry::units::NAUTICAL_MILE_M),
                    Readable(steps.round()),
                    Readable(config.step_m)
                ),
            ));
        }
        Ok(())
    }

    fn check_clearance(&self, config: &PlannerConfig) -> Result<(), (String, String)> {
        let own = self.ownship.start_position_m();
        for (index, target) in self.targets.iter().enumerate() {
            let range = own.distance(target.start_position_m());
            if range < config.clearance_m {
                return Err((
                    Who::Target(index, &target.name).field(start_field(target)),
                    format!(
                        "is {range:.1} m from ownship's start, inside the planner clearance of {} m",
                        Readable(config.clearance_m)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// No target that never moves (at anchor: speed 0, or its goal where it
    /// starts; a `Noisy` target's speed wanders, so it moves) lies nearer
    /// ownship's goal than the distance ownship must keep from it (`d_th`
    /// plus their contact range, as the planner keeps it:
    /// `SafetyChecker::required_distance_m`). No plan can then end at the
    /// goal, and a run would only fail every plan and sail on past it
    /// (issue 24; decision 33).
    fn check_goal_clear(&self, config: &PlannerConfig) -> Result<(), (String, String)> {
        let Some(goal) = self.ownship.goal_position_m() else {
            return Ok(());
        };
        let goal_field = if self.ownship.goal_nm.is_some() {
            "goal_nm"
        } else if self.ownship.goal_m.is_some() {
            "goal_m"
        } else {
            "goal_lat_lon"
        };
        for (index, target) in self.targets.iter().enumerate() {
            let start = target.start_position_m();
            let at_rest = !matches!(target.behaviour, crate::Behaviour::Noisy { .. })
                && (target.speed_kn == 0.0
                    || (target.behaviour.announces_goal()
                        && target.goal_position_m() == Some(start)));
            if !at_rest {
                continue;
            }
            let required_m =
                config.clearance_m + rules::contact_range_m(self.ownship.length_m, target.length_m);
            let range_m = goal.distance(start);
            if range_m < required_m {
                return Err((
                    Who::Target(index, &target.name).field(start_field(target)),
                    format!(
                        "lies at rest {} m from ownship's goal (ownship.{goal_field}), nearer than the {} m ownship must keep from it (planner clearance {} m plus half the two lengths): no plan can reach that goal; move ownship's goal at least {} m from the vessel",
                        Readable(range_m.round()),
                        Readable(required_m.round()),
                        Readable(config.clearance_m),
                        Readable(required_m.ceil()),
                    ),
                ));
            }
        }
        Ok(())
    }

    fn check_simulation(&self) -> Result<(), (String, String)> {
        let settings = &self.simulation;
        let positive = [
            ("time_step_s", Some(settings.time_step_s)),
            ("max_duration_s", settings.max_duration_s),
            ("replan_deviation_m", Some(settings.replan_deviation_m)),
        ];
        for (name, value) in positive {
            if let Some(value) = value.filter(|value| !(value.is_finite() && *value > 0.0)) {
                return Err((
                    format!("simulation.{name}"),
                    format!(
                        "is {}, expected a finite number greater than 0",
                        Readable(value)
                    ),
                ));
            }
        }
        let steps = self.max_duration_s() / settings.time_step_s;
        if steps > MAX_SIMULATION_STEPS {
            return Err((
                "simulation.time_step_s".into(),
                format!(
                    "makes {} steps of the {} s simulation, more than the {MAX_SIMULATION_STEPS} allowed",
                    Readable(steps.round()),
                    Readable(self.max_duration_s())
                ),
            ));
        }
        Ok(())
    }
}

fn check_position(
    who: Who<'_>,
    field: &str,
    position: Option<(f64, f64)>,
    scale_to_nm: f64,
) -> Result<(), (String, String)> {
    let Some((east, north)) = position else {
        return Ok(());
    };
    for value in [east, north] {
        if !value.is_finite() {
            return Err((
                who.field(field),
                format!("holds {}, not a finite number", Readable(value)),
            ));
        }
    }
    if east.hypot(north) * scale_to_nm > MAX_EXTENT_NM {
        return Err((
            who.field(field),
            format!("is more than {MAX_EXTENT_NM} nm from the origin"),
        ));
    }
    Ok(())
}

/// Normalises a course in degrees into `[0, 360)`.
fn normalise_course_deg(course_deg: f64) -> f64 {
    let course = course_deg.rem_euclid(360.0);
    // rem_euclid of a tiny negative number rounds to 360.
    if course >= 360.0 { 0.0 } else { course }
}

/// The fastest rate of turn a vessel may give, degrees per second (a
/// planing craft turns at well under 30°/s).
pub const MAX_TURN_RATE_DEG_S: f64 = 30.0;

fn check_vessel(vessel: &mut VesselSpec, who: Who<'_>) -> Result<(), (String, String)> {
    check_name(&vessel.name).map_err(|problem| (who.field("name"), problem))?;
    if let Some(rate) = vessel.max_turn_rate_deg_s
        && !(rate.is_finite() && rate > 0.0 && rate <= MAX_TURN_RATE_DEG_S)
    {
        return Err((
            who.field("max_turn_rate_deg_s"),
            format!(
                "is {}, expected a rate of turn greater than 0 and at most {MAX_TURN_RATE_DEG_S} °/s",
                Readable(rate)
            ),
        ));
    }
    let m_to_nm = 1.0 / vorrt_geometry::units::NAUTICAL_MILE_M;
    check_position(who, "start_nm", vessel.start_nm, 1.0)?;
    check_position(who, "start_m", vessel.start_m, m_to_nm)?;
    check_position(who, "goal_nm", vessel.goal_nm, 1.0)?;
    check_position(who, "goal_m", vessel.goal_m, m_to_nm)?;
    match (vessel.start_nm, vessel.start_m) {
        (Some(_), Some(_)) => {
            return Err((
                who.field("start_nm"),
                "and start_m are both given: give exactly one of them".into(),
            ));
        }
        (None, None) if vessel.start_lat_lon.is_none() => {
            return Err((
                who.field("start_nm"),
                "is missing: give exactly one of start_nm and start_m".into(),
            ));
        }
        _ => {}
    }
    if vessel.goal_nm.is_some() && vessel.goal_m.is_some() {
        return Err((
            who.field("goal_nm"),
            "and goal_m are both given: give at most one of them".into(),
        ));
    }
    let numbers = [
        ("course_deg", vessel.course_deg),
        ("speed_kn", vessel.speed_kn),
        ("length_m", vessel.length_m),
    ];
    for (field, value) in numbers {
        if !value.is_finite() {
            return Err((
                who.field(field),
                format!("is {}, not a finite number", Readable(value)),
            ));
        }
    }
    vessel.course_deg = normalise_course_deg(vessel.course_deg);
    if vessel.speed_kn < 0.0 {
        return Err((
            who.field("speed_kn"),
            format!(
                "is {}, speeds must not be negative",
                Readable(vessel.speed_kn)
            ),
        ));
    }
    if vessel.speed_kn > MAX_SPEED_KN {
        return Err((
            who.field("speed_kn"),
            format!(
                "is {}, more than the {MAX_SPEED_KN} kn allowed",
                Readable(vessel.speed_kn)
            ),
        ));
    }
    if !(vessel.length_m > 0.0 && vessel.length_m <= MAX_LENGTH_M) {
        return Err((
            who.field("length_m"),
            format!(
                "is {}, expected more than 0 and at most {MAX_LENGTH_M} m",
                Readable(vessel.length_m)
            ),
        ));
    }
    vessel
        .behaviour
        .check()
        .map_err(|(field, problem)| (who.field(&format!("behaviour.{field}")), problem))?;
    Ok(())
}

fn check_ownship(ownship: &VesselSpec) -> Result<(), (String, String)> {
    let who = Who::Ownship;
    if ownship.speed_mps() < vorrt_planner::problem::MIN_OWNSHIP_SPEED_MPS {
        return Err((
            who.field("speed_kn"),
            format!(
                "is {}, ownship must move: at least {} kn",
                Readable(ownship.speed_kn),
                Readable(vorrt_geometry::units::mps_to_knots(
                    vorrt_planner::problem::MIN_OWNSHIP_SPEED_MPS
                ))
            ),
        ));
    }
    let Some(goal) = ownship.goal_position_m() else {
        return Err((
            who.field("goal_nm"),
            "is missing: ownship needs a goal (goal_nm or goal_m; goal_lat_lon in a geographic scenario)".into(),
        ));
    };
    if goal == ownship.start_position_m() {
        let field = if ownship.goal_nm.is_some() {
            "goal_nm"
        } else if ownship.goal_m.is_some() {
            "goal_m"
        } else {
            "goal_lat_lon"
        };
        return Err((
            who.field(field),
            "is ownship's start: it must differ".into(),
        ));
    }
    Ok(())
}

fn check_lane(index: usize, lane: &Lane) -> Result<(), (String, String)> {
    let field = |name: &str| format!("lanes[{index}] {:?}.{name}", lane.name);
    check_name(&lane.name).map_err(|problem| (field("name"), problem))?;
    check_position(Who::Ownship, "", lane.from_nm, 1.0).map_err(|(_, p)| (field("from_nm"), p))?;
    check_position(Who::Ownship, "", lane.to_nm, 1.0).map_err(|(_, p)| (field("to_nm"), p))?;
    if !(lane.width_nm.is_finite() && lane.width_nm > 0.0 && lane.width_nm <= MAX_EXTENT_NM) {
        return Err((
            field("width_nm"),
            format!(
                "is {}, expected a finite number greater than 0 and at most {MAX_EXTENT_NM} nm",
                Readable(lane.width_nm)
            ),
        ));
    }
    // Ends were projected (geographic) or checked above by now.
    if lane.from_m() == lane.to_m() {
        let name = if lane.to_nm.is_some() {
            "to_nm"
        } else {
            "to_lat_lon"
        };
        return Err((
            field(name),
            "is the same point as the lane's other end: a lane needs a direction".into(),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[expect(clippy::float_cmp, reason = "the test pins exact results")]
    fn courses_normalise_into_range() {
        assert_eq!(normalise_course_deg(-90.0), 270.0);
        assert_eq!(normalise_course_deg(360.0), 0.0);
        assert_eq!(normalise_course_deg(725.0), 5.0);
        assert_eq!(normalise_course_deg(-1e-20), 0.0);
        assert_eq!(normalise_course_deg(0.0), 0.0);
    }
}
