//! A traffic separation scheme in a scenario file (rule 10): the
//! separation zones and rule-10 tolerances beside the [`Lane`]s, their
//! validation and projection, and the scheme the planner and the judge
//! share ([`Scenario::traffic_scheme`], [`scenario_constraint`]).
//!
//! A zone is a polygon (`vertices_nm`, `vertices_m` or, in a geographic
//! scenario, `vertices_lat_lon`); a strip between two lanes is the
//! four-cornered case. Its axis, the flow a crossing vessel crosses square,
//! is that of the nearest lane (from the zone's centroid to the lane's
//! centre line), or with no lane the direction of its longest edge.

use crate::geo::{LocalFrame, MAX_GEO_EXTENT_NM, ProjectedPositions, check_lat_lon};
use crate::scenario::{Lane, Scenario};
use crate::validate::MAX_EXTENT_NM;
use serde::{Deserialize, Serialize};
use vorrt_colregs::rule10::{Rule10Parameters, Scheme, SeparationZone, TrafficLane};
use vorrt_geometry::{DVec2, angle, units};
use vorrt_planner::error::Readable;
use vorrt_planner::scheme::SchemeConstraint;

/// A separation zone of a traffic separation scheme (written
/// `SeparationZone(...)` in RON): exactly one of `vertices_nm`,
/// `vertices_m` (local scenarios) and `vertices_lat_lon` (geographic ones).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename = "SeparationZone")]
pub struct SeparationZoneSpec {
    /// Name, e.g. `"central"`.
    pub name: String,
    /// The polygon's vertices `(east, north)` in order, nautical miles; at
    /// least three, not closed (the last joins the first).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices_nm: Option<Vec<(f64, f64)>>,
    /// The same in metres.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices_m: Option<Vec<(f64, f64)>>,
    /// The same as `(latitude, longitude)`, degrees WGS84.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices_lat_lon: Option<Vec<(f64, f64)>>,
    /// `vertices_lat_lon` in the scenario's local frame: derived by
    /// [`Scenario::validate`], not part of the file.
    #[serde(skip)]
    pub projected_m: Vec<DVec2>,
}

impl SeparationZoneSpec {
    /// A zone with its vertices in nautical miles.
    #[must_use]
    pub fn new_nm(name: impl Into<String>, vertices_nm: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            vertices_nm: Some(vertices_nm),
            vertices_m: None,
            vertices_lat_lon: None,
            projected_m: Vec::new(),
        }
    }

    /// The vertices in metres (of a validated scenario).
    #[must_use]
    pub fn vertices_in_m(&self) -> Vec<DVec2> {
        if let Some(vertices) = &self.vertices_nm {
            vertices.iter().map(|&(e, n)| nm(e, n)).collect()
        } else if let Some(vertices) = &self.vertices_m {
            vertices.iter().map(|&v| DVec2::from(v)).collect()
        } else {
            self.projected_m.clone()
        }
    }
}

/// The tolerances of rule 10 (written `rule10: (...)`; every field
/// optional, defaults of [`Rule10Parameters`]: 15° and 30°, decision 30).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Rule10Settings {
    /// A lane crossing's heading may be this far from perpendicular to the
    /// flow, degrees (10(c)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crossing_tolerance_deg: Option<f64>,
    /// A heading this near the flow is with it, as near its reverse against
    /// it, degrees (10(b)(i), (iii)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flow_tolerance_deg: Option<f64>,
}

impl Rule10Settings {
    /// Whether no field is set.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// The tolerances in radians, defaults where unset.
    #[must_use]
    pub fn parameters(&self) -> Rule10Parameters {
        let defaults = Rule10Parameters::default();
        Rule10Parameters {
            crossing_tolerance_rad: self
                .crossing_tolerance_deg
                .map_or(defaults.crossing_tolerance_rad, f64::to_radians),
            flow_tolerance_rad: self
                .flow_tolerance_deg
                .map_or(defaults.flow_tolerance_rad, f64::to_radians),
        }
    }
}

fn nm(east: f64, north: f64) -> DVec2 {
    DVec2::new(
        units::nautical_miles_to_m(east),
        units::nautical_miles_to_m(north),
    )
}

impl Scenario {
    /// The scenario's traffic separation scheme in metres, as the planner
    /// and the judge read it (empty without lanes and zones). The scenario
    /// must have been validated (geographic lanes and zones projected).
    ///
    /// ```
    /// let scenario = vorrt_scenarios::fixtures::find("paper/tss").unwrap().load().unwrap();
    /// let scheme = scenario.traffic_scheme();
    /// assert_eq!(scheme.lanes.len(), 1);
    /// assert!((scheme.lanes[0].flow_course_rad().to_degrees() - 270.0).abs() < 1e-9);
    /// ```
    #[must_use]
    pub fn traffic_scheme(&self) -> Scheme {
        let lanes: Vec<TrafficLane> = self
            .lanes
            .iter()
            .map(|lane| TrafficLane {
                from_m: lane.from_m(),
                to_m: lane.to_m(),
                width_m: lane.width_m(),
            })
            .collect();
        let zones = self
            .separation_zones
            .iter()
            .map(|zone| {
                let vertices_m = zone.vertices_in_m();
                let axis_course_rad = zone_axis_rad(&vertices_m, &lanes);
                SeparationZone {
                    vertices_m,
                    axis_course_rad,
                }
            })
            .collect();
        Scheme {
            lanes,
            zones,
            parameters: self.rule10.parameters(),
        }
    }
}

/// The planner's constraint for `scenario`: its traffic separation scheme
/// (rule 10; an empty scheme, which refuses nothing, without lanes). The
/// one place the closed loop and `vorrt plan` get it from.
#[must_use]
pub fn scenario_constraint(scenario: &Scenario) -> SchemeConstraint {
    SchemeConstraint::new(
        scenario.traffic_scheme(),
        scenario.ownship_state().position_m,
        scenario.ownship_goal_m(),
    )
}

/// The axis of a zone: the nearest lane's flow, else its longest edge.
fn zone_axis_rad(vertices_m: &[DVec2], lanes: &[TrafficLane]) -> f64 {
    #[expect(clippy::cast_precision_loss, reason = "a handful of vertices")]
    let centroid = vertices_m.iter().copied().sum::<DVec2>() / vertices_m.len().max(1) as f64;
    let distance = |lane: &TrafficLane| {
        let (along, across) = lane.lane_coordinates_m(centroid);
        let length = lane.from_m.distance(lane.to_m);
        across.hypot((along - along.clamp(0.0, length)).abs())
    };
    if let Some(lane) = lanes
        .iter()
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))
    {
        return lane.flow_course_rad();
    }
    let mut longest = (0.0, DVec2::Y);
    for (index, &vertex) in vertices_m.iter().enumerate() {
        let next = vertices_m[(index + 1) % vertices_m.len()];
        let edge = next - vertex;
        if edge.length() > longest.0 {
            longest = (edge.length(), edge);
        }
    }
    angle::unit_to_course(longest.1)
}

/// Checks the scheme's fields, and projects geographic lanes and zones
/// into `frame` (`None`: a local scenario, where no `*_lat_lon` may be
/// given). Run by [`Scenario::validate`].
pub(crate) fn check_scheme(
    scenario: &mut Scenario,
    frame: Option<&LocalFrame>,
) -> Result<(), (String, String)> {
    for (index, lane) in scenario.lanes.iter_mut().enumerate() {
        let field = |name: &str| format!("lanes[{index}] {:?}.{name}", lane.name);
        lane.projected = ProjectedPositions::default();
        for (end, nautical, geographic) in [
            ("from", lane.from_nm, lane.from_lat_lon),
            ("to", lane.to_nm, lane.to_lat_lon),
        ] {
            let position = match (frame, nautical, geographic) {
                (None, Some(_), None) => None,
                (Some(frame), None, Some(lat_lon)) => Some(
                    project(frame, lat_lon).map_err(|p| (field(&format!("{end}_lat_lon")), p))?,
                ),
                (None, _, Some(_)) => {
                    return Err((
                        field(&format!("{end}_lat_lon")),
                        "is given in a local scenario: use from_nm and to_nm".into(),
                    ));
                }
                (Some(_), Some(_), _) => {
                    return Err((
                        field(&format!("{end}_nm")),
                        "is given in a geographic scenario: use from_lat_lon and to_lat_lon".into(),
                    ));
                }
                (_, None, None) => {
                    let name = if frame.is_some() { "lat_lon" } else { "nm" };
                    return Err((field(&format!("{end}_{name}")), "is missing".into()));
                }
            };
            if end == "from" {
                lane.projected.start_m = position;
            } else {
                lane.projected.goal_m = position;
            }
        }
    }
    for (index, zone) in scenario.separation_zones.iter_mut().enumerate() {
        check_zone(index, zone, frame)?;
    }
    for (name, value) in [
        (
            "crossing_tolerance_deg",
            scenario.rule10.crossing_tolerance_deg,
        ),
        ("flow_tolerance_deg", scenario.rule10.flow_tolerance_deg),
    ] {
        if let Some(value) = value
            && !(value.is_finite() && value > 0.0 && value <= 45.0)
        {
            return Err((
                format!("rule10.{name}"),
                format!(
                    "is {}, expected an angle greater than 0 and at most 45 degrees",
                    Readable(value)
                ),
            ));
        }
    }
    Ok(())
}

fn project(frame: &LocalFrame, lat_lon: (f64, f64)) -> Result<DVec2, String> {
    check_lat_lon(lat_lon)?;
    let position_m = frame.to_local_m(lat_lon.0, lat_lon.1);
    let distance_nm = position_m.length() / units::NAUTICAL_MILE_M;
    if distance_nm.is_nan() || distance_nm > MAX_GEO_EXTENT_NM {
        return Err(format!(
            "is {distance_nm:.1} nm from the origin (ownship's start), more than the {MAX_GEO_EXTENT_NM} nm a geographic scenario may span"
        ));
    }
    Ok(position_m)
}

/// Checks one zone: one vertex field, the right one for the scenario's
/// frame, at least three finite vertices within range, some area.
fn check_zone(
    index: usize,
    zone: &mut SeparationZoneSpec,
    frame: Option<&LocalFrame>,
) -> Result<(), (String, String)> {
    let field = |name: &str| format!("separation_zones[{index}] {:?}.{name}", zone.name);
    if zone.name.trim().is_empty() {
        return Err((field("name"), "is empty".into()));
    }
    let name = zone_field(zone, frame).map_err(|(name, problem)| (field(name), problem))?;
    let raw = zone
        .vertices_nm
        .as_ref()
        .or(zone.vertices_m.as_ref())
        .or(zone.vertices_lat_lon.as_ref())
        .cloned()
        .unwrap_or_default();
    if raw.len() < 3 {
        return Err((
            field(name),
            format!("has {} vertices: a zone needs at least 3", raw.len()),
        ));
    }
    let scale_to_nm = if name == "vertices_m" {
        1.0 / units::NAUTICAL_MILE_M
    } else {
        1.0
    };
    let mut vertices_m = Vec::with_capacity(raw.len());
    for (at, &vertex) in raw.iter().enumerate() {
        let bad = |problem: String| (format!("{}[{at}]", field(name)), problem);
        if !(vertex.0.is_finite() && vertex.1.is_finite()) {
            return Err(bad("holds a number that is not finite".into()));
        }
        let point = if let Some(frame) = frame {
            project(frame, vertex).map_err(bad)?
        } else {
            if vertex.0.hypot(vertex.1) * scale_to_nm > MAX_EXTENT_NM {
                return Err(bad(format!(
                    "is more than {MAX_EXTENT_NM} nm from the origin"
                )));
            }
            if name == "vertices_nm" {
                nm(vertex.0, vertex.1)
            } else {
                DVec2::from(vertex)
            }
        };
        vertices_m.push(point);
    }
    let twice_area: f64 = (0..vertices_m.len())
        .map(|i| vertices_m[i].perp_dot(vertices_m[(i + 1) % vertices_m.len()]))
        .sum();
    if twice_area.abs() < 1.0 {
        return Err((
            field(name),
            "encloses no area: its vertices lie on one line".into(),
        ));
    }
    zone.projected_m = if frame.is_some() {
        vertices_m
    } else {
        Vec::new()
    };
    Ok(())
}

/// The one vertex field a zone gives, right for the scenario's frame, or
/// the field at fault and what is wrong.
fn zone_field(
    zone: &SeparationZoneSpec,
    frame: Option<&LocalFrame>,
) -> Result<&'static str, (&'static str, String)> {
    let given: Vec<&'static str> = [
        ("vertices_nm", zone.vertices_nm.is_some()),
        ("vertices_m", zone.vertices_m.is_some()),
        ("vertices_lat_lon", zone.vertices_lat_lon.is_some()),
    ]
    .iter()
    .filter(|(_, given)| *given)
    .map(|(name, _)| *name)
    .collect();
    let name = match given.as_slice() {
        [one] => *one,
        [] => {
            return Err((
                "vertices_nm",
                "is missing: give vertices_nm, vertices_m or vertices_lat_lon".into(),
            ));
        }
        [_, second, ..] => {
            return Err((second, "is given twice: give one vertex field".into()));
        }
    };
    match (name, frame) {
        ("vertices_lat_lon", None) => {
            return Err((
                name,
                "is given in a local scenario: use vertices_nm or vertices_m".into(),
            ));
        }
        ("vertices_nm" | "vertices_m", Some(_)) => {
            return Err((
                name,
                "is given in a geographic scenario: use vertices_lat_lon".into(),
            ));
        }
        _ => {}
    }
    Ok(name)
}

/// The lane helpers of a validated scenario, geographic ends included.
impl Lane {
    /// A lane from `from_nm` to `to_nm` (east, north; nautical miles),
    /// `width_nm` wide.
    #[must_use]
    pub fn new_nm(
        name: impl Into<String>,
        from_nm: (f64, f64),
        to_nm: (f64, f64),
        width_nm: f64,
    ) -> Self {
        Self {
            name: name.into(),
            from_nm: Some(from_nm),
            to_nm: Some(to_nm),
            width_nm,
            from_lat_lon: None,
            to_lat_lon: None,
            projected: ProjectedPositions::default(),
        }
    }
}

#[cfg(test)]
mod tests;
