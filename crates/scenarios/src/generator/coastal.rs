//! Coastal encounters: an open-sea encounter (its targets in the drawn
//! encounter types and behaviour) with islands and a coast drawn near
//! ownship's route, redrawn until every start and goal is clear of land
//! (decision 41).

use super::random::{round_to, uniform, uniform_in};
use super::{GeneratorError, OpenSeaSpec, open_sea};
use crate::area::Area;
use crate::chart::Chart;
use crate::scenario::Scenario;
use glam::DVec2;
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;
use vorrt_geometry::{closest_point_of_approach, units};

/// A coastal encounter: the open-sea encounter of [`open_sea`] with
/// `open_sea` (ownship north from the origin for 8-12 nm, every target on a
/// near-collision course), plus land near the route:
///
/// - `islands` star-shaped islands (5-12 vertices, radii 0.4-1 of a radius
///   drawn in `island_radius_nm`), centred within `island_offset_nm` east or
///   west of the route and at least 1 nm along it from the start and the
///   goal, so an island may lie across the route; with probability
///   `lagoon_probability` an island has a hole (a lagoon: water inside);
/// - with probability `coast_probability` a coast on one side, parallel to
///   the route at `coast_offset_nm`, from 3 nm south of the start to 3 nm
///   north of the goal, 6 nm deep; with probability `headland_probability`
///   a headland juts out of it towards the route (to `headland_tip_nm` from
///   it) and with probability `bay_probability` a bay cuts into it.
///
/// A draw of land is kept when ownship's start and goal are
/// `route_margin_nm` beyond the planner's land clearance
/// (`land_clearance_m` and half ownship's length), every target's start is
/// at least the land clearance from land and every target's straight track
/// from its start to 10 minutes past its closest approach with ownship
/// keeps that clearance (a target does not sail through an island into its
/// encounter), and islands keep the land clearance from each other and the
/// coast; otherwise the land is drawn again, up to `max_land_attempts`
/// times. Where none of those draws is kept (many targets sweep most of the
/// water near the route), the land is drawn sparser, `max_land_attempts`
/// times each: first one island and the coast half as often, then one
/// island of the smallest radius and no coast
/// ([`CoastalSpec::land_grades`]); the scenario's description says how much
/// land it got. The targets are those of [`open_sea`] for the same seed and
/// index; the land comes from a stream of its own.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CoastalSpec {
    /// The route and the targets.
    pub open_sea: OpenSeaSpec,
    /// Range of the number of islands (inclusive).
    pub islands: (usize, usize),
    /// Range of an island's radius, nautical miles.
    pub island_radius_nm: (f64, f64),
    /// Largest offset of an island's centre east or west of the route,
    /// nautical miles.
    pub island_offset_nm: f64,
    /// Probability that an island has a lagoon (a hole).
    pub lagoon_probability: f64,
    /// Probability of a coast on one side of the route.
    pub coast_probability: f64,
    /// Range of the coast's distance from the route, nautical miles.
    pub coast_offset_nm: (f64, f64),
    /// Probability that the coast has a headland.
    pub headland_probability: f64,
    /// Range of the distance of a headland's tip from the route, nautical
    /// miles.
    pub headland_tip_nm: (f64, f64),
    /// Probability that the coast has a bay.
    pub bay_probability: f64,
    /// Margin of ownship's start and goal beyond the planner's land
    /// clearance, nautical miles.
    pub route_margin_nm: f64,
    /// The scenario's `land_clearance_m`; `None` for the format's default.
    pub land_clearance_m: Option<f64>,
    /// Draws of land allowed before giving up.
    pub max_land_attempts: usize,
}

impl CoastalSpec {
    /// The defaults with `targets` targets: 1-2 islands of 0.2-0.6 nm within
    /// 0.8 nm of the route, lagoons 30 %, a coast 1.5-2.5 nm off half the
    /// time, headlands (tip 0.7-1.2 nm off) and bays half the coasts,
    /// margin 0.1 nm, 500 draws.
    #[must_use]
    pub fn with_targets(targets: usize) -> Self {
        Self {
            open_sea: OpenSeaSpec::with_targets(targets),
            islands: (1, 2),
            island_radius_nm: (0.2, 0.6),
            island_offset_nm: 0.8,
            lagoon_probability: 0.3,
            coast_probability: 0.5,
            coast_offset_nm: (1.5, 2.5),
            headland_probability: 0.5,
            headland_tip_nm: (0.7, 1.2),
            bay_probability: 0.5,
            route_margin_nm: 0.1,
            land_clearance_m: None,
            max_land_attempts: 500,
        }
    }

    /// The grades of land tried in turn, densest first: this spec, then
    /// one island with the coast half as likely, then one island of the
    /// smallest radius and no coast (a grade equal to the one before is
    /// left out). The route, the targets and every margin stay as they are.
    #[must_use]
    pub fn land_grades(&self) -> Vec<Self> {
        let one_island = (self.islands.0.min(1), self.islands.1.min(1));
        let smallest_nm = self.island_radius_nm.0;
        let mut grades = vec![*self];
        for grade in [
            Self {
                islands: one_island,
                coast_probability: self.coast_probability / 2.0,
                ..*self
            },
            Self {
                islands: one_island,
                coast_probability: 0.0,
                island_radius_nm: (smallest_nm, smallest_nm),
                ..*self
            },
        ] {
            if grades.last() != Some(&grade) {
                grades.push(grade);
            }
        }
        grades
    }

    /// The same with another behaviour of the targets.
    #[must_use]
    pub fn with_behaviour(mut self, behaviour: super::TargetBehaviour) -> Self {
        self.open_sea = self.open_sea.with_behaviour(behaviour);
        self
    }

    pub(super) fn check(&self) -> Result<(), GeneratorError> {
        self.open_sea.check()?;
        let (fewest, most) = self.islands;
        if fewest > most || most > 8 {
            return Err(GeneratorError::InvalidSpec(format!(
                "islands is ({fewest}, {most}), expected low <= high <= 8"
            )));
        }
        super::check_range("island_radius_nm", self.island_radius_nm, 0.05, 2.0)?;
        super::check_range("coast_offset_nm", self.coast_offset_nm, 0.3, 20.0)?;
        super::check_range("headland_tip_nm", self.headland_tip_nm, 0.2, 20.0)?;
        if self.headland_tip_nm.1 >= self.coast_offset_nm.0 {
            return Err(GeneratorError::InvalidSpec(format!(
                "headland_tip_nm reaches {} nm, expected under the nearest coast_offset_nm {} nm",
                self.headland_tip_nm.1, self.coast_offset_nm.0
            )));
        }
        for (name, value) in [
            ("lagoon_probability", self.lagoon_probability),
            ("coast_probability", self.coast_probability),
            ("headland_probability", self.headland_probability),
            ("bay_probability", self.bay_probability),
        ] {
            if !(0.0..=1.0).contains(&value) {
                return Err(GeneratorError::InvalidSpec(format!(
                    "{name} is {value}, expected a probability in [0, 1]"
                )));
            }
        }
        let positive = [
            ("island_offset_nm", self.island_offset_nm, 0.0, 10.0),
            ("route_margin_nm", self.route_margin_nm, 0.0, 5.0),
            (
                "land_clearance_m",
                self.land_clearance_m.unwrap_or(0.0),
                0.0,
                5000.0,
            ),
        ];
        for (name, value, min, max) in positive {
            if !(value.is_finite() && (min..=max).contains(&value)) {
                return Err(GeneratorError::InvalidSpec(format!(
                    "{name} is {value}, expected a number in [{min}, {max}]"
                )));
            }
        }
        if self.max_land_attempts == 0 {
            return Err(GeneratorError::InvalidSpec(
                "max_land_attempts must be at least 1".into(),
            ));
        }
        Ok(())
    }
}

/// The stream of a scenario's land draws: separate from its targets' (the
/// open-sea stream) and its behaviours'.
fn land_stream(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x1A4D_C0A5_7000_0041);
    rng.set_stream(index);
    rng
}

fn chance(rng: &mut ChaCha8Rng, probability: f64) -> bool {
    uniform(rng, 0.0, 1.0) < probability
}

/// A ring of `vertices` points about `centre_nm`, radii in
/// `[low, high] x radius_nm`: star-shaped about the centre, so simple.
fn star_ring(
    rng: &mut ChaCha8Rng,
    centre_nm: (f64, f64),
    radius_nm: f64,
    (low, high): (f64, f64),
    vertices: usize,
) -> Vec<(f64, f64)> {
    #[expect(clippy::cast_precision_loss, reason = "a dozen vertices")]
    let count = vertices as f64;
    (0..vertices)
        .map(|vertex| {
            #[expect(clippy::cast_precision_loss, reason = "a dozen vertices")]
            let angle = TAU * (vertex as f64 + 0.4 * uniform(rng, 0.0, 1.0)) / count;
            let radius = radius_nm * uniform(rng, low, high);
            (
                round_to(centre_nm.0 + radius * angle.cos(), 4),
                round_to(centre_nm.1 + radius * angle.sin(), 4),
            )
        })
        .collect()
}

/// An island about `centre_nm`, maybe with a lagoon inside its inner radius
/// (the outer ring keeps at least 0.4 of `radius_nm` from the centre, the
/// lagoon at most 0.25).
fn island(
    rng: &mut ChaCha8Rng,
    spec: &CoastalSpec,
    name: String,
    centre_nm: (f64, f64),
    radius_nm: f64,
) -> Area {
    let vertices = 5 + usize::try_from(rng.next_u64() % 8).unwrap_or(0);
    let mut area = Area::from_nm(
        name,
        star_ring(rng, centre_nm, radius_nm, (0.4, 1.0), vertices),
    );
    if chance(rng, spec.lagoon_probability) {
        area.holes_nm
            .push(star_ring(rng, centre_nm, radius_nm, (0.15, 0.25), 8));
    }
    area
}

/// A coast on `side` (+1 east, -1 west) of a route from north 0 to
/// `goal_nm`, maybe with a headland and a bay (in different halves).
fn coast(rng: &mut ChaCha8Rng, spec: &CoastalSpec, side: f64, goal_nm: f64) -> Area {
    let near = uniform_in(rng, spec.coast_offset_nm);
    let far = near + 6.0;
    let (south, north) = (-3.0, goal_nm + 3.0);
    let headland_south = chance(rng, 0.5);
    let half = |southern: bool| {
        if southern {
            (0.5, 0.5 * goal_nm - 0.5)
        } else {
            (0.5 * goal_nm + 0.5, goal_nm - 0.5)
        }
    };
    // The shore from south to north, with its features in order.
    let mut shore = vec![(near, south)];
    let mut features: Vec<(f64, Vec<(f64, f64)>)> = Vec::new();
    if chance(rng, spec.headland_probability) {
        let at = uniform_in(rng, half(headland_south));
        let tip = uniform_in(rng, spec.headland_tip_nm);
        let width = uniform(rng, 0.3, 0.8);
        features.push((at, vec![(near, at - width), (tip, at), (near, at + width)]));
    }
    if chance(rng, spec.bay_probability) {
        let at = uniform_in(rng, half(!headland_south));
        let depth = uniform(rng, 0.5, 2.0);
        let width = uniform(rng, 0.4, 1.0);
        features.push((
            at,
            vec![
                (near, at - width),
                (near + depth, at - 0.5 * width),
                (near + depth, at + 0.5 * width),
                (near, at + width),
            ],
        ));
    }
    features.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (_, points) in features {
        shore.extend(points);
    }
    shore.push((near, north));
    shore.push((far, north));
    shore.push((far, south));
    let outer_nm = shore
        .into_iter()
        .map(|(east, north)| (round_to(side * east, 4), round_to(north, 4)))
        .collect();
    Area::from_nm(
        if side > 0.0 {
            "east coast"
        } else {
            "west coast"
        },
        outer_nm,
    )
}

/// One draw of land for a route north to `goal_nm`: islands (apart from
/// each other by `apart_nm` beyond their radii) and maybe a coast.
fn draw_land(rng: &mut ChaCha8Rng, spec: &CoastalSpec, goal_nm: f64, apart_nm: f64) -> Vec<Area> {
    let (fewest, most) = spec.islands;
    let span = u64::try_from(most - fewest + 1).unwrap_or(1);
    let count = fewest + usize::try_from(rng.next_u64() % span).unwrap_or(0);
    let mut land = Vec::new();
    let mut placed: Vec<((f64, f64), f64)> = Vec::new();
    for number in 0..count {
        let centre = (
            round_to(
                uniform(rng, -spec.island_offset_nm, spec.island_offset_nm),
                3,
            ),
            round_to(uniform(rng, 1.0, goal_nm - 1.0), 3),
        );
        let radius_nm = uniform_in(rng, spec.island_radius_nm);
        let overlaps = placed.iter().any(|&((east, north), radius)| {
            (centre.0 - east).hypot(centre.1 - north) < radius + radius_nm + apart_nm
        });
        if overlaps {
            continue;
        }
        placed.push((centre, radius_nm));
        land.push(island(
            rng,
            spec,
            format!("island {}", number + 1),
            centre,
            radius_nm,
        ));
    }
    if chance(rng, spec.coast_probability) {
        let side = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
        let coast = coast(rng, spec, side, goal_nm);
        // An island keeps the clearance from the shore (so a passage between
        // them is water, not a slit).
        let nearest_shore = placed
            .iter()
            .map(|&((east, _), radius)| side * east + radius)
            .fold(f64::NEG_INFINITY, f64::max);
        let shore_nm = coast.outer_nm.as_ref().map_or(0.0, |ring| {
            ring.iter()
                .map(|p| side * p.0)
                .fold(f64::INFINITY, f64::min)
        });
        if nearest_shore + apart_nm < shore_nm {
            land.push(coast);
        }
    }
    land
}

/// Whether `scenario` (validated, with its land) keeps the promises of
/// [`CoastalSpec`]: ownship's start and goal, the targets' starts and their
/// tracks into the encounter clear of land.
fn clear_of_land(scenario: &Scenario, margin_m: f64) -> bool {
    let Ok(chart) = Chart::from_scenario(scenario) else {
        return false;
    };
    let route_m = chart.planner_land_clearance_m() + margin_m;
    let own = scenario.ownship_state();
    if chart.land_distance_m(own.position_m) < route_m
        || chart.land_distance_m(scenario.ownship_goal_m()) < route_m
    {
        return false;
    }
    scenario.targets.iter().all(|target| {
        let state = target.state();
        let cpa = closest_point_of_approach(
            own.position_m,
            own.velocity_mps(),
            state.position_m,
            state.velocity_mps(),
        );
        let end_m: DVec2 = state.position_m + state.velocity_mps() * (cpa.time_s.max(0.0) + 600.0);
        chart.segment_land_distance_m(state.position_m, end_m) >= chart.land_clearance_m()
    })
}

/// Scenario `index` of a coastal batch seeded with `seed` (see
/// [`CoastalSpec`]); validated.
///
/// # Errors
/// [`GeneratorError::InvalidSpec`] for a bad specification, as
/// [`open_sea`] for the targets, and [`GeneratorError::LandPlacement`]
/// when no draw of land keeps every start and goal clear in
/// `max_land_attempts` draws.
pub fn coastal(spec: &CoastalSpec, seed: u64, index: u64) -> Result<Scenario, GeneratorError> {
    spec.check()?;
    let mut scenario = open_sea(&spec.open_sea, seed, index)?;
    scenario.land_clearance_m = spec.land_clearance_m;
    let goal_nm = scenario.ownship.goal_nm.map_or(10.0, |(_, north)| north);
    let apart_nm = units::m_to_nautical_miles(scenario.land_clearance_m()) + 0.1;
    let margin_m = units::nautical_miles_to_m(spec.route_margin_nm);
    let mut rng = land_stream(seed, index);
    let grades = spec.land_grades();
    let draws = grades
        .iter()
        .flat_map(|grade| std::iter::repeat_n(grade, spec.max_land_attempts));
    for grade in draws {
        let mut candidate = scenario.clone();
        candidate.land = draw_land(&mut rng, grade, goal_nm, apart_nm);
        if candidate.validate().is_ok() && clear_of_land(&candidate, margin_m) {
            let islands = candidate
                .land
                .iter()
                .filter(|area| area.name.starts_with("island"))
                .count();
            let coast = candidate.land.len() > islands;
            candidate.name = candidate.name.replacen("open-sea", "coastal", 1);
            candidate.source = candidate.source.replacen("open-sea", "coastal", 1);
            candidate.description = candidate.description.map(|text| {
                format!(
                    "{} Land: {islands} island(s){}.",
                    text.replacen("open-sea", "coastal", 1),
                    if coast { " and a coast" } else { "" }
                )
            });
            return Ok(candidate);
        }
    }
    Err(GeneratorError::LandPlacement {
        index,
        attempts: spec.max_land_attempts * grades.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn land_clears_every_start_and_goal() {
        let spec = CoastalSpec::with_targets(1);
        for index in 0..8 {
            let scenario = coastal(&spec, 3, index).expect("generated");
            assert!(!scenario.land.is_empty(), "{}", scenario.name);
            assert!(clear_of_land(&scenario, 0.0), "{}", scenario.name);
            assert!(scenario.name.starts_with("coastal-"), "{}", scenario.name);
        }
    }

    #[test]
    fn a_bad_spec_is_refused_by_field() {
        let mut spec = CoastalSpec::with_targets(1);
        spec.coast_probability = 1.5;
        let error = coastal(&spec, 1, 0).expect_err("refused");
        assert!(error.to_string().contains("coast_probability"), "{error}");
        let mut spec = CoastalSpec::with_targets(1);
        spec.headland_tip_nm = (0.5, 3.0);
        let error = coastal(&spec, 1, 0).expect_err("refused");
        assert!(error.to_string().contains("headland_tip_nm"), "{error}");
    }

    #[test]
    fn the_land_keeps_its_promises_over_many_draws() {
        // Coasts, headlands, bays and lagoons all occur (the generator's
        // documented mix), and no draw gives up.
        let spec = CoastalSpec::with_targets(1);
        let (mut coasts, mut lagoons, mut headlands, mut bays) = (0, 0, 0, 0);
        for index in 0..40 {
            let scenario = coastal(&spec, 5, index).expect("generated");
            for area in &scenario.land {
                lagoons += usize::from(!area.holes_nm.is_empty());
                if area.name.ends_with("coast") {
                    coasts += 1;
                    let ring = area.outer_nm.as_ref().expect("nm");
                    // 4 corners, 3 points a headland, 4 a bay.
                    headlands += usize::from(matches!(ring.len(), 7 | 11));
                    bays += usize::from(matches!(ring.len(), 8 | 11));
                }
            }
        }
        assert!(coasts >= 4, "{coasts} coasts");
        assert!(lagoons >= 4, "{lagoons} lagoons");
        assert!(headlands >= 1, "{headlands} headlands");
        assert!(
            bays >= 1,
            "{bays} bays {coasts} coasts {headlands} headlands"
        );
    }

    #[test]
    fn land_grades_go_from_the_spec_to_one_small_island() {
        let spec = CoastalSpec::with_targets(1);
        let grades = spec.land_grades();
        assert_eq!(grades.len(), 3);
        assert_eq!(grades[0], spec);
        assert_eq!(grades[1].islands, (1, 1));
        assert!((grades[1].coast_probability - 0.25).abs() < 1e-12);
        assert_eq!(grades[2].islands, (1, 1));
        assert!(grades[2].coast_probability.abs() < 1e-12);
        assert_eq!(grades[2].island_radius_nm, (0.2, 0.2));
        // Already the sparsest: nothing sparser is invented.
        assert_eq!(grades[2].land_grades(), vec![grades[2]]);
    }

    #[test]
    fn many_targets_get_sparser_land_instead_of_no_scenario() {
        // Seed 11 index 136 with 8 targets: none of 500 draws of the
        // default land kept every target's track clear, and the batch gave
        // up; a sparser grade is kept.
        let spec = CoastalSpec::with_targets(8);
        let scenario = coastal(&spec, 11, 136).expect("generated");
        assert!(!scenario.land.is_empty(), "{}", scenario.name);
        assert!(clear_of_land(&scenario, 0.0), "{}", scenario.name);
    }
}
