//! Land in the closed loop (decision 29): the bundled coastal fixtures and
//! generated coastal scenarios (seeded random islands and a coast near the
//! route, random crossing targets) are sailed without coming within
//! `land_clearance_m` of land, checked independently of the constraint
//! code: the sailed track is sampled every few metres and each sample
//! measured against the polygons by `geo`'s own distance.
//!
//! 6 generated cases in a debug run; `VORRT_HEAVY_TESTS=1` runs 96.

use geo::{Distance, Euclidean, LineString, Point, Polygon};
use proptest::prelude::*;
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use vorrt_scenarios::{Area, Scenario, SimulationRecord, VesselSpec, evaluate, fixtures, simulate};

const NM: f64 = 1852.0;

fn cases() -> u32 {
    if std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1") {
        96
    } else {
        6
    }
}

/// The polygons of `areas` in metres, from their rings in nautical miles as
/// written (not the scenario's projection).
fn polygons_m(areas: &[Area]) -> Vec<Polygon<f64>> {
    let ring = |points: &[(f64, f64)]| {
        LineString::from(
            points
                .iter()
                .map(|&(x, y)| (x * NM, y * NM))
                .collect::<Vec<_>>(),
        )
    };
    areas
        .iter()
        .map(|area| {
            Polygon::new(
                ring(area.outer_nm.as_deref().expect("given in nm")),
                area.holes_nm.iter().map(|hole| ring(hole)).collect(),
            )
        })
        .collect()
}

/// The least distance from ownship's sailed track to `polygons`, metres,
/// sampling every step of the record at most 5 m apart.
fn sampled_land_distance_m(record: &SimulationRecord, polygons: &[Polygon<f64>]) -> f64 {
    let mut least_m = f64::INFINITY;
    for pair in record.ownship.windows(2) {
        let (from, to) = (pair[0].position_m, pair[1].position_m);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a step of at most a few hundred metres"
        )]
        let samples = (from.distance(to) / 5.0).ceil().max(1.0) as usize;
        for index in 0..=samples {
            #[expect(clippy::cast_precision_loss, reason = "a few dozen samples")]
            let point = from.lerp(to, index as f64 / samples as f64);
            let point = Point::new(point.x, point.y);
            for polygon in polygons {
                least_m = least_m.min(Euclidean.distance(&point, polygon));
            }
        }
    }
    least_m
}

/// Runs `scenario`, checks the track by sampling and the evaluation's own
/// judgement, and returns the sampled least distance to land.
fn sail_and_check(scenario: &Scenario, seed: u64) -> Result<f64, String> {
    let record = simulate(scenario, seed).map_err(|error| error.to_string())?;
    let evaluation = evaluate(scenario, &record);
    let sampled_m = sampled_land_distance_m(&record, &polygons_m(&scenario.land));
    let clearance_m = scenario.land_clearance_m();
    if sampled_m < clearance_m {
        return Err(format!(
            "{}: the track came {sampled_m:.1} m from land, within {clearance_m:.0} m",
            scenario.name
        ));
    }
    if evaluation.grounding || !evaluation.land_clearance_kept {
        return Err(format!("{}: judged {evaluation:?}", scenario.name));
    }
    // The judgement's lower bound is within a few metres of the sampled
    // distance (the sampled chords are no nearer than the curve).
    let judged_m = evaluation.min_land_distance_m.ok_or("land not judged")?;
    if judged_m > sampled_m + 1e-6 || judged_m < sampled_m - 10.0 {
        return Err(format!(
            "{}: judged {judged_m:.1} m, sampled {sampled_m:.1} m",
            scenario.name
        ));
    }
    if evaluation.collision {
        return Err(format!("{}: collision", scenario.name));
    }
    Ok(sampled_m)
}

#[test]
fn the_island_across_the_route_is_rounded_clear() {
    let scenario = fixtures::find("coastal/island")
        .expect("bundled")
        .load()
        .expect("valid");
    let record = simulate(&scenario, 1).expect("runs");
    let evaluation = evaluate(&scenario, &record);
    assert!(evaluation.success(), "{}", evaluation.table());
    let sampled_m = sail_and_check(&scenario, 1).expect("clear of land");
    // Without the island ownship sails through it: the track bends around.
    let mut open_sea = scenario.clone();
    open_sea.land.clear();
    open_sea.validate().expect("valid");
    let straight = simulate(&open_sea, 1).expect("runs");
    let through_m = sampled_land_distance_m(&straight, &polygons_m(&scenario.land));
    assert!(through_m <= 0.0, "{through_m}");
    assert!(evaluation.path_overhead_pct > 0.5, "{}", evaluation.table());
    assert!(sampled_m < 0.5 * NM, "{sampled_m}");
}

#[test]
fn a_crossing_with_a_coast_to_starboard_keeps_off_it() {
    let scenario = fixtures::find("coastal/crossing_coast")
        .expect("bundled")
        .load()
        .expect("valid");
    let record = simulate(&scenario, 1).expect("runs");
    let evaluation = evaluate(&scenario, &record);
    sail_and_check(&scenario, 1).expect("clear of land");
    assert!(evaluation.success(), "{}", evaluation.table());
    // Ownship still gives way to TS1 (rules 15, 16), within what the coast
    // leaves it: here by slowing and passing astern (rule 8(e)), judged
    // compliant; the time overhead is the speed change.
    assert!(!evaluation.collision && evaluation.clearance_kept);
    assert!(evaluation.compliant, "{}", evaluation.table());
    assert!(
        evaluation.time_overhead_pct > evaluation.path_overhead_pct + 5.0,
        "{}",
        evaluation.table()
    );
    // The same crossing in the open sea turns to starboard more boldly than
    // the coast allows: the coast changed the manoeuvre.
    let mut open_sea = scenario.clone();
    open_sea.land.clear();
    open_sea.validate().expect("valid");
    let open_record = simulate(&open_sea, 1).expect("runs");
    let eastmost = |record: &SimulationRecord| {
        record
            .ownship
            .iter()
            .filter(|state| state.position_m.y < -0.3 * NM)
            .map(|state| state.position_m.x)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    assert!(
        eastmost(&record) < 0.55 * NM - scenario.land_clearance_m(),
        "{}",
        eastmost(&record)
    );
    assert!(
        eastmost(&open_record) > eastmost(&record),
        "open sea {} vs coast {}",
        eastmost(&open_record),
        eastmost(&record)
    );
}

fn unit(rng: &mut ChaCha8Rng) -> f64 {
    #[expect(clippy::cast_precision_loss, reason = "53 random bits are exact")]
    let value = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    value
}

/// A star-shaped island about `centre_nm` (simple by construction), radii in
/// `[0.4, 1] x radius_nm`.
fn island(rng: &mut ChaCha8Rng, name: &str, centre_nm: (f64, f64), radius_nm: f64) -> Area {
    let vertices = 5 + usize::try_from(rng.next_u64() % 8).unwrap_or(0);
    #[expect(clippy::cast_precision_loss, reason = "a dozen vertices")]
    let outer_nm = (0..vertices)
        .map(|index| {
            let angle = std::f64::consts::TAU * (index as f64 + 0.4 * unit(rng)) / vertices as f64;
            let radius = radius_nm * (0.4 + 0.6 * unit(rng));
            (
                centre_nm.0 + radius * angle.cos(),
                centre_nm.1 + radius * angle.sin(),
            )
        })
        .collect();
    Area::from_nm(name, outer_nm)
}

/// A generated coastal scenario: ownship north along a 6 nm route, one or
/// two islands within a mile of the route (maybe across it), maybe a coast
/// to one side, and one crossing target on a collision course; `None` when
/// the draw puts ownship's start or goal too near land (validation refuses
/// it) or leaves no way through.
fn coastal_scenario(seed: u64) -> Option<Scenario> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut land = Vec::new();
    let islands = 1 + rng.next_u64() % 2;
    for index in 0..islands {
        let centre = (1.6 * unit(&mut rng) - 0.8, 3.0 * unit(&mut rng) - 1.5);
        let radius_nm = 0.2 + 0.4 * unit(&mut rng);
        land.push(island(
            &mut rng,
            &format!("island {index}"),
            centre,
            radius_nm,
        ));
    }
    if rng.next_u64() % 2 == 0 {
        // A straight coast 1.5-2 nm to one side, beyond the islands.
        let side = if rng.next_u64() % 2 == 0 { 1.0 } else { -1.0 };
        let near = side * (1.5 + 0.5 * unit(&mut rng));
        let far = side * 5.0;
        land.push(Area::from_nm(
            "coast",
            vec![(near, -5.0), (far, -5.0), (far, 5.0), (near, 5.0)],
        ));
    }
    // A crossing target from either side, meeting ownship's straight route
    // at the same moment.
    let side = if rng.next_u64() % 2 == 0 { 1.0 } else { -1.0 };
    let meet_y_nm = 2.0 * unit(&mut rng) - 1.0;
    let time_h = (meet_y_nm + 3.0) / 12.0;
    let speed_kn = 8.0 + 6.0 * unit(&mut rng);
    let bearing = side * (60.0 + 60.0 * unit(&mut rng)).to_radians();
    let start = (
        bearing.sin() * speed_kn * time_h,
        meet_y_nm + bearing.cos() * speed_kn * time_h,
    );
    let course_deg = (bearing.to_degrees() + 180.0).rem_euclid(360.0);
    let goal = (start.0 - bearing.sin() * 8.0, start.1 - bearing.cos() * 8.0);
    let mut scenario = Scenario::from_ron_str(
        "(name: \"coastal\", ownship: Vessel(name: \"ownship\", start_nm: (0.0, -3.0), course_deg: 0.0, speed_kn: 12.0, length_m: 100.0, goal_nm: (0.0, 3.0)), planner: (nodes_per_phase: 600))",
        "<generated>",
    )
    .ok()?;
    scenario.name = format!("coastal-{seed}");
    scenario.targets =
        vec![VesselSpec::new("TS1", start, course_deg, speed_kn, 120.0).with_goal_nm(goal)];
    scenario.land = land;
    scenario.validate().ok()?;
    Some(scenario)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn generated_coastal_runs_keep_off_land(seed in 0u64..1_000_000) {
        // Draws that validation refuses (start or goal near land, a target
        // on land) are drawn again; the others must be sailed clear of land.
        let scenario = coastal_scenario(seed);
        prop_assume!(scenario.is_some());
        if let Some(scenario) = scenario {
            sail_and_check(&scenario, seed).map_err(TestCaseError::fail)?;
        }
    }
}

#[test]
fn the_generator_draws_valid_scenarios_often() {
    let valid = (0..40).filter_map(coastal_scenario).count();
    assert!(valid >= 10, "{valid} of 40");
}
