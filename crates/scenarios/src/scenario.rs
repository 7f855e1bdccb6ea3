//! The scenario data types: what a scenario file holds, field for field.
//!
//! Field names carry their units (`_nm`, `_m`, `_kn`, `_deg`, `_s`); positions
//! are `(east, north)` tuples. See `docs/scenario-format.md` for the format.

use crate::area::{Area, DEFAULT_LAND_CLEARANCE_M};
use crate::geo::{
    LocalFrame, MAX_GEO_EXTENT_NM, ProjectedPositions, check_lat_lon, parse_utc_time,
};
use crate::planner_settings::PlannerSettings;
use crate::recorded_tracks::RecordedTracks;
use crate::scheme::{Rule10Settings, SeparationZoneSpec};
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use time::OffsetDateTime;
use vorrt_geometry::{DVec2, units};

/// One encounter to plan or simulate: ownship, its goal, the targets, and
/// optional planner, simulation and traffic-lane settings.
///
/// Build one by hand, or load one with [`Scenario::from_ron_str`],
/// [`Scenario::load`] or [`load_dir`](crate::load_dir); loading validates
/// (see [`Scenario::validate`]).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Short name, e.g. `"crossing"`. Must not be empty.
    pub name: String,
    /// What the scenario is and where its numbers come from.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// The vessel being planned for. It must move (speed > 0) and have a goal.
    pub ownship: VesselSpec,
    /// The other vessels, at most [`MAX_TARGETS`](crate::MAX_TARGETS).
    #[serde(default)]
    pub targets: Vec<VesselSpec>,
    /// Planner settings in file units; absent fields take
    /// `PlannerConfig::default()`.
    #[serde(default, skip_serializing_if = "PlannerSettings::is_empty")]
    pub planner: PlannerSettings,
    /// Closed-loop simulation settings.
    #[serde(default, skip_serializing_if = "SimulationSettings::is_default")]
    pub simulation: SimulationSettings,
    /// Traffic lanes of a traffic separation scheme (rule 10), if any.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub lanes: Vec<Lane>,
    /// Land: islands and coasts ownship keeps `land_clearance_m` from
    /// (decision 29). See [`Area`].
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub land: Vec<Area>,
    /// Areas ownship must keep out of (an exercise area, a wreck): no
    /// clearance beyond its own hull. See [`Area`].
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub no_go: Vec<Area>,
    /// A `GeoJSON` file (RFC 7946) whose polygons are added to `land`
    /// (geographic scenarios only). A relative path is resolved from the
    /// scenario file's directory ([`Scenario::load`]), or from the current
    /// directory for a scenario read from text ([`Scenario::from_ron_str`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub land_geojson: Option<String>,
    /// The distance ownship's track keeps from land, metres (>= 0); default
    /// [`DEFAULT_LAND_CLEARANCE_M`]. The planner keeps half ownship's length
    /// more, so that its hull keeps it too.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub land_clearance_m: Option<f64>,
    /// The polygons read from `land_geojson`, validated and projected like
    /// `land`: derived by [`Scenario::validate`], not part of the file.
    #[serde(skip)]
    pub geojson_land: Vec<Area>,
    /// The directory a relative `land_geojson` is resolved from: set by
    /// [`Scenario::load`] (the file's directory); `None` is the current
    /// directory. Not part of the file.
    #[serde(skip)]
    pub base_dir: Option<PathBuf>,
    /// Separation zones of the scheme (rule 10(e)), if any.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub separation_zones: Vec<SeparationZoneSpec>,
    /// Rule 10's tolerances; absent fields take the defaults (decision 30).
    #[serde(default, skip_serializing_if = "Rule10Settings::is_empty")]
    pub rule10: Rule10Settings,
    /// The planner seed to use when none is given elsewhere.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// The wall-clock time of simulation time 0, ISO 8601 in UTC
    /// (`"2024-05-01T12:00:00Z"`); timestamps exported trajectories. See
    /// [`Scenario::start_time_utc`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_time: Option<String>,
    /// Where the scenario came from: the file path given to
    /// [`Scenario::load`] or the source name given to
    /// [`Scenario::from_ron_str`]; used in error messages. Not part of the
    /// file, not written out, and ignored by `==`.
    #[serde(skip)]
    pub source: String,
    /// The recorded tracks its [`Behaviour::Recorded`] targets follow: a CSV
    /// file (`vessel,time_s` and `lat_deg,lon_deg` or `east_m,north_m`,
    /// optional `course_deg,speed_kn`), its path relative to the scenario
    /// file's folder. Read by [`Scenario::load`] into `recorded`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub recorded_tracks: Option<String>,
    /// The tracks read from `recorded_tracks`, per vessel name, in the
    /// scenario's frame (times in seconds from the run's start; decision 40).
    /// Not part of the file; empty until [`Scenario::load`] reads them.
    #[serde(skip)]
    pub recorded: RecordedTracks,
}

impl PartialEq for Scenario {
    fn eq(&self, other: &Self) -> bool {
        // Destructured so that a new field cannot be forgotten here.
        let Scenario {
            name,
            description,
            ownship,
            targets,
            planner,
            simulation,
            lanes,
            land,
            no_go,
            land_geojson,
            land_clearance_m,
            geojson_land: _,
            base_dir: _,
            separation_zones,
            rule10,
            seed,
            start_time,
            source: _,
            recorded_tracks,
            recorded,
        } = self;
        *name == other.name
            && *description == other.description
            && *ownship == other.ownship
            && *targets == other.targets
            && *planner == other.planner
            && *simulation == other.simulation
            && *lanes == other.lanes
            && *land == other.land
            && *no_go == other.no_go
            && *land_geojson == other.land_geojson
            && *land_clearance_m == other.land_clearance_m
            && *separation_zones == other.separation_zones
            && *rule10 == other.rule10
            && *seed == other.seed
            && *start_time == other.start_time
            && *recorded_tracks == other.recorded_tracks
            && *recorded == other.recorded
    }
}

impl Scenario {
    /// A scenario called `name` with `ownship` and nothing else: no targets,
    /// default planner and simulation settings, no lanes, no land, no seed.
    /// Not yet validated ([`Scenario::validate`]).
    ///
    /// ```
    /// use vorrt_scenarios::{Scenario, VesselSpec};
    /// let own = VesselSpec::new("own", (0.0, 0.0), 0.0, 10.0, 50.0).with_goal_nm((0.0, 4.0));
    /// let mut scenario = Scenario::new("empty sea", own);
    /// scenario.validate().unwrap();
    /// assert!(scenario.targets.is_empty() && scenario.land.is_empty());
    /// ```
    #[must_use]
    pub fn new(name: impl Into<String>, ownship: VesselSpec) -> Self {
        Self {
            name: name.into(),
            description: None,
            ownship,
            targets: Vec::new(),
            planner: PlannerSettings::default(),
            simulation: SimulationSettings::default(),
            lanes: Vec::new(),
            land: Vec::new(),
            no_go: Vec::new(),
            land_geojson: None,
            land_clearance_m: None,
            geojson_land: Vec::new(),
            base_dir: None,
            separation_zones: Vec::new(),
            rule10: crate::scheme::Rule10Settings::default(),
            seed: None,
            start_time: None,
            source: String::new(),
            recorded_tracks: None,
            recorded: RecordedTracks::default(),
        }
    }

    /// Whether the scenario places its vessels in latitude and longitude
    /// (ownship has a `start_lat_lon`).
    #[must_use]
    pub fn is_geographic(&self) -> bool {
        self.ownship.start_lat_lon.is_some()
    }

    /// The local frame of a geographic scenario (about ownship's start), or
    /// `None` for a local one.
    #[must_use]
    pub fn local_frame(&self) -> Option<LocalFrame> {
        self.ownship
            .start_lat_lon
            .map(|(lat_deg, lon_deg)| LocalFrame::new(lat_deg, lon_deg))
    }

    /// The distance ownship's track keeps from land, metres:
    /// `land_clearance_m`, or [`DEFAULT_LAND_CLEARANCE_M`].
    #[must_use]
    pub fn land_clearance_m(&self) -> f64 {
        self.land_clearance_m.unwrap_or(DEFAULT_LAND_CLEARANCE_M)
    }

    /// Every land area: `land`, then the polygons of `land_geojson`.
    pub fn land_areas(&self) -> impl Iterator<Item = &Area> {
        self.land.iter().chain(&self.geojson_land)
    }

    /// The `start_time`, in UTC, if the scenario has a valid one.
    #[must_use]
    pub fn start_time_utc(&self) -> Option<OffsetDateTime> {
        self.start_time
            .as_deref()
            .and_then(|text| parse_utc_time(text).ok())
    }

    /// Checks the geographic fields and projects every `*_lat_lon` into the
    /// local frame ([`VesselSpec::projected`]); clears the projections of a
    /// local scenario. Run by [`Scenario::validate`].
    pub(crate) fn check_geographic(&mut self) -> Result<(), (String, String)> {
        if let Some(text) = &self.start_time {
            parse_utc_time(text).map_err(|problem| ("start_time".to_owned(), problem))?;
        }
        let frame = match self.ownship.start_lat_lon {
            Some(origin) => {
                check_lat_lon(origin)
                    .map_err(|problem| ("ownship.start_lat_lon".to_owned(), problem))?;
                Some(LocalFrame::new(origin.0, origin.1))
            }
            None => None,
        };
        project_vessel(&mut self.ownship, "ownship", frame.as_ref())?;
        for (index, target) in self.targets.iter_mut().enumerate() {
            let who = format!("targets[{index}] {:?}", target.name);
            project_vessel(target, &who, frame.as_ref())?;
        }
        Ok(())
    }
}

/// Projects a vessel's `*_lat_lon` into `frame` ([`VesselSpec::projected`]),
/// or checks that a local scenario's vessel has none.
fn project_vessel(
    vessel: &mut VesselSpec,
    who: &str,
    frame: Option<&LocalFrame>,
) -> Result<(), (String, String)> {
    let field = |name: &str| format!("{who}.{name}");
    let Some(frame) = frame else {
        vessel.projected = ProjectedPositions::default();
        for (name, value) in [
            ("start_lat_lon", vessel.start_lat_lon),
            ("goal_lat_lon", vessel.goal_lat_lon),
        ] {
            if value.is_some() {
                return Err((
                    field(name),
                    "is given in a local scenario: a scenario is all geographic (ownship has start_lat_lon) or all local".into(),
                ));
            }
        }
        return Ok(());
    };
    let local_fields = [
        ("start_nm", vessel.start_nm.is_some()),
        ("start_m", vessel.start_m.is_some()),
        ("goal_nm", vessel.goal_nm.is_some()),
        ("goal_m", vessel.goal_m.is_some()),
    ];
    if let Some((name, _)) = local_fields.iter().find(|(_, given)| *given) {
        return Err((
            field(name),
            "is given in a geographic scenario: a scenario is all geographic or all local; use start_lat_lon and goal_lat_lon".into(),
        ));
    }
    let Some(start) = vessel.start_lat_lon else {
        return Err((
            field("start_lat_lon"),
            "is missing: every vessel of a geographic scenario needs one".into(),
        ));
    };
    let project = |name: &str, lat_lon: (f64, f64)| -> Result<DVec2, (String, String)> {
        check_lat_lon(lat_lon).map_err(|problem| (field(name), problem))?;
        let position_m = frame.to_local_m(lat_lon.0, lat_lon.1);
        let distance_nm = position_m.length() / units::NAUTICAL_MILE_M;
        if distance_nm.is_nan() || distance_nm > MAX_GEO_EXTENT_NM {
            return Err((
                field(name),
                format!(
                    "is {distance_nm:.1} nm from the origin (ownship's start), more than the {MAX_GEO_EXTENT_NM} nm a geographic scenario may span"
                ),
            ));
        }
        Ok(position_m)
    };
    let start_m = project("start_lat_lon", start)?;
    let goal_m = vessel
        .goal_lat_lon
        .map(|goal| project("goal_lat_lon", goal))
        .transpose()?;
    vessel.projected = ProjectedPositions {
        start_m: Some(start_m),
        goal_m,
    };
    Ok(())
}

/// One vessel as a scenario file gives it (written `Vessel(...)` in RON).
///
/// Exactly one of `start_nm` / `start_m` must be given, and at most one of
/// `goal_nm` / `goal_m` (ownship needs one). Positions are `(east, north)`.
/// In a geographic scenario (see [`crate::geo`]) every vessel gives
/// `start_lat_lon` (and `goal_lat_lon`) instead.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename = "Vessel")]
pub struct VesselSpec {
    /// Unique, non-empty name (`"ownship"`, `"TS1"`, ...).
    pub name: String,
    /// Start position `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_nm: Option<(f64, f64)>,
    /// Start position `(east, north)`, metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_m: Option<(f64, f64)>,
    /// Course over ground, degrees clockwise from north. Loading normalises it
    /// into `[0, 360)`. A goal-bound target steers for its goal at once, so its
    /// course is then replaced by the bearing of its goal.
    pub course_deg: f64,
    /// Speed over ground, knots. Ownship: > 0. Targets: >= 0 (0 = at anchor).
    pub speed_kn: f64,
    /// Length overall, metres (> 0): the radius of the vessel's disc.
    pub length_m: f64,
    /// Goal `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_nm: Option<(f64, f64)>,
    /// Goal `(east, north)`, metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_m: Option<(f64, f64)>,
    /// How a target moves. Ignored for ownship (which the planner steers).
    #[serde(default, skip_serializing_if = "Behaviour::is_default")]
    pub behaviour: Behaviour,
    /// Start position `(latitude, longitude)`, degrees WGS84 (geographic
    /// scenarios only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_lat_lon: Option<(f64, f64)>,
    /// Goal `(latitude, longitude)`, degrees WGS84 (geographic scenarios only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goal_lat_lon: Option<(f64, f64)>,
    /// The vessel's MMSI (AIS identity), when known.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mmsi: Option<u32>,
    /// The vessel's largest rate of turn, degrees per second. For ownship it
    /// bounds every turn the planner plans and the closed loop sails; unset,
    /// it comes from the length and speed (`vorrt_jfs::default_turn_rate_rad_s`).
    /// Targets turn as their behaviour says (instantaneously in this
    /// simulation), so on a target it is checked but not used.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_turn_rate_deg_s: Option<f64>,
    /// `start_lat_lon` and `goal_lat_lon` in the scenario's local frame:
    /// derived by [`Scenario::validate`], not part of the file.
    #[serde(skip)]
    pub projected: ProjectedPositions,
}

impl VesselSpec {
    /// A vessel starting at `start_nm` (east, north; nautical miles) with no
    /// goal and the default behaviour.
    #[must_use]
    pub fn new(
        name: impl Into<String>,
        start_nm: (f64, f64),
        course_deg: f64,
        speed_kn: f64,
        length_m: f64,
    ) -> Self {
        Self {
            name: name.into(),
            start_nm: Some(start_nm),
            start_m: None,
            course_deg,
            speed_kn,
            length_m,
            goal_nm: None,
            goal_m: None,
            behaviour: Behaviour::default(),
            start_lat_lon: None,
            goal_lat_lon: None,
            mmsi: None,
            max_turn_rate_deg_s: None,
            projected: ProjectedPositions::default(),
        }
    }

    /// The same vessel bound for `goal_nm` (east, north; nautical miles).
    #[must_use]
    pub fn with_goal_nm(mut self, goal_nm: (f64, f64)) -> Self {
        self.goal_nm = Some(goal_nm);
        self.goal_m = None;
        self
    }

    /// The same vessel with another behaviour.
    #[must_use]
    pub fn with_behaviour(mut self, behaviour: Behaviour) -> Self {
        self.behaviour = behaviour;
        self
    }
}

/// How a target vessel moves during a scenario.
///
/// Written in RON as a bare variant name, `behaviour: ConstantVelocity`, or
/// with its fields, `behaviour: SuddenTurn(at_s: 600.0, turn_deg: 60.0)`.
///
/// Whatever a target really does, ownship predicts it from what it announces
/// (AIS: its destination, course and speed): a target bound for a goal is
/// predicted steering straight for it at its nominal speed, one without a goal
/// (or a [`SuddenTurn`](Self::SuddenTurn) target after its turn) holding its
/// course and speed. A target that strays from that prediction by more than
/// `simulation.replan_deviation_m` makes ownship replan.
///
/// Match with a wildcard arm outside this crate: more variants may come.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Behaviour {
    /// The paper's assumption (notes, erratum 9): steer straight for the goal
    /// at constant speed and stop there. Without a goal: hold course and speed.
    #[default]
    ConstantToGoal,
    /// Hold course and speed for ever, ignoring any goal.
    ConstantVelocity,
    /// Steer for the goal as [`ConstantToGoal`](Self::ConstantToGoal), but
    /// obey COLREGs toward ownship: when there is risk of collision with
    /// ownship and the target's own role (the encounter classified from the
    /// target's side) is give-way — head-on, crossing with ownship on its
    /// starboard side, or overtaking ownship — it turns
    /// [`COLREGS_TURN_DEG`] to starboard from the course it held when the
    /// risk arose and holds that course until the two have passed, then
    /// resumes toward its goal; while its return would at once bring risk
    /// of collision with ownship back, it holds its alteration up to 30 s
    /// longer (decision 43). As stand-on vessel it keeps course and speed.
    /// The rule constants are the scenario's (`planner` section).
    Colregs,
    /// Steer for the goal (or hold the nominal course without one) with
    /// course and speed wandering about the nominal: each is offset by a
    /// mean-reverting random walk (Ornstein-Uhlenbeck, time constant
    /// [`NOISE_TIME_CONSTANT_S`]) whose standard deviation is the given sigma.
    /// The noise comes from a `ChaCha8` stream per target derived from the run
    /// seed, so a run is reproducible.
    Noisy {
        /// Standard deviation of the course offset, degrees (≥ 0).
        course_sigma_deg: f64,
        /// Standard deviation of the speed offset, knots (≥ 0). The speed
        /// never goes below 0.
        speed_sigma_kn: f64,
    },
    /// Move as [`ConstantToGoal`](Self::ConstantToGoal) until `at_s`, then
    /// turn by `turn_deg` (positive to starboard, clockwise) at once and hold
    /// the new course and speed for ever, abandoning the goal. A target that
    /// has already arrived stays where it is.
    SuddenTurn {
        /// Simulation time of the turn, seconds (≥ 0).
        at_s: f64,
        /// The course change, degrees, positive to starboard (in `[-180, 180]`).
        turn_deg: f64,
    },
    /// Follow the target's track in the scenario's `recorded_tracks` file
    /// (the row's `vessel` is the target's name), interpolated between its
    /// recorded states and dead-reckoned beyond them. Ownship's planner sees
    /// only the last state recorded by then, dead-reckoned (decision 40).
    Recorded,
}

/// How far a [`Behaviour::Colregs`] target turns to starboard when it gives
/// way, degrees: more than the 30° evaluators call "readily apparent".
pub const COLREGS_TURN_DEG: f64 = 35.0;

/// Time constant of the course and speed noise of [`Behaviour::Noisy`],
/// seconds: offsets decorrelate over a few minutes.
pub const NOISE_TIME_CONSTANT_S: f64 = 120.0;

impl Behaviour {
    /// Whether this is the default, [`Behaviour::ConstantToGoal`].
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }

    /// Checks the variant's fields: `Err((field, problem))` naming the first
    /// field that is not finite or out of range (e.g. `"course_sigma_deg"`).
    ///
    /// # Errors
    /// The field's name and what is wrong with it.
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        let fields: Vec<(&'static str, f64, f64, f64)> = match *self {
            Behaviour::ConstantToGoal
            | Behaviour::ConstantVelocity
            | Behaviour::Colregs
            | Behaviour::Recorded => Vec::new(),
            Behaviour::Noisy {
                course_sigma_deg,
                speed_sigma_kn,
            } => vec![
                ("course_sigma_deg", course_sigma_deg, 0.0, 180.0),
                ("speed_sigma_kn", speed_sigma_kn, 0.0, 100.0),
            ],
            Behaviour::SuddenTurn { at_s, turn_deg } => vec![
                ("at_s", at_s, 0.0, f64::MAX),
                ("turn_deg", turn_deg, -180.0, 180.0),
            ],
        };
        for (field, value, low, high) in fields {
            if !value.is_finite() {
                return Err((field, format!("is {value}, not a finite number")));
            }
            if !(low..=high).contains(&value) {
                #[expect(
                    clippy::float_cmp,
                    reason = "`f64::MAX` is the exact no-upper-bound sentinel"
                )]
                let range = if high == f64::MAX {
                    format!("at least {low}")
                } else {
                    format!("in [{low}, {high}]")
                };
                return Err((field, format!("is {value}, expected a number {range}")));
            }
        }
        Ok(())
    }

    /// Whether the target announces (and ownship predicts) a goal it steers
    /// for: every behaviour but [`ConstantVelocity`](Self::ConstantVelocity)
    /// and [`Recorded`](Self::Recorded).
    #[must_use]
    pub fn announces_goal(&self) -> bool {
        !matches!(self, Behaviour::ConstantVelocity | Behaviour::Recorded)
    }
}

/// Settings of a closed-loop simulation of the scenario (written
/// `Simulation(...)` in RON; every field optional).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default, rename = "Simulation")]
pub struct SimulationSettings {
    /// Simulation time step, seconds. Default 5.0.
    pub time_step_s: f64,
    /// Longest simulated time, seconds. Default (`None`): three times the time
    /// ownship needs to sail straight to its goal (see
    /// [`Scenario::max_duration_s`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_duration_s: Option<f64>,
    /// Ownship replans when a target is this far from where the plan
    /// predicted it, metres. Default 50.0.
    pub replan_deviation_m: f64,
}

/// Default simulation time step, seconds.
pub const DEFAULT_TIME_STEP_S: f64 = 5.0;
/// Default replanning threshold, metres.
pub const DEFAULT_REPLAN_DEVIATION_M: f64 = 50.0;
/// Default longest simulated time, as a multiple of ownship's straight-line
/// time to its goal.
pub const DEFAULT_DURATION_FACTOR: f64 = 3.0;

impl Default for SimulationSettings {
    fn default() -> Self {
        Self {
            time_step_s: DEFAULT_TIME_STEP_S,
            max_duration_s: None,
            replan_deviation_m: DEFAULT_REPLAN_DEVIATION_M,
        }
    }
}

impl SimulationSettings {
    /// Whether every field has its default.
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }
}

/// One traffic lane of a traffic separation scheme: a strip `width_nm` wide
/// centred on the line from `from_nm` to `to_nm` (in a geographic scenario
/// `from_lat_lon` to `to_lat_lon`), traffic flowing from `from` toward `to`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lane {
    /// Name, e.g. `"westbound"`.
    pub name: String,
    /// Upstream end of the centre line `(east, north)`, nautical miles
    /// (local scenarios).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_nm: Option<(f64, f64)>,
    /// Downstream end of the centre line `(east, north)`, nautical miles.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to_nm: Option<(f64, f64)>,
    /// Upstream end `(latitude, longitude)`, degrees WGS84 (geographic
    /// scenarios).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_lat_lon: Option<(f64, f64)>,
    /// Downstream end `(latitude, longitude)`, degrees WGS84.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to_lat_lon: Option<(f64, f64)>,
    /// `from_lat_lon` (as `start_m`) and `to_lat_lon` (as `goal_m`) in the
    /// local frame: derived by [`Scenario::validate`], not part of the file.
    #[serde(skip)]
    pub projected: ProjectedPositions,
    /// Full width of the lane, nautical miles (> 0).
    pub width_nm: f64,
}
