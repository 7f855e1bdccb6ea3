//! Land in the closed loop (decision 29): the bundled coastal fixtures and
//! generated coastal scenarios (`vorrt_scenarios::generator::coastal`,
//! decision 41: islands and a coast near the route, targets in every
//! encounter type) are sailed without coming within
//! `land_clearance_m` of land, checked independently of the constraint
//! code: the sailed track is sampled every few metres and each sample
//! measured against the polygons by `geo`'s own distance.
//!
//! 6 generated cases in a debug run; `VORRT_HEAVY_TESTS=1` runs 96.

use geo::{Distance, Euclidean, LineString, Point, Polygon};
use proptest::prelude::*;
use vorrt_scenarios::generator::{CoastalSpec, TargetBehaviour, coastal};
use vorrt_scenarios::{Area, Scenario, SimulationRecord, evaluate, fixtures, simulate};

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

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn generated_coastal_runs_keep_off_land(seed in 0u64..1_000_000) {
        // The library's generator (decision 41): every draw it gives must
        // be sailed clear of land, without grounding or collision.
        let scenario = coastal(&CoastalSpec::with_targets(1), seed, 0)
            .map_err(|error| TestCaseError::fail(error.to_string()))?;
        sail_and_check(&scenario, seed).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn the_generator_is_deterministic_and_keeps_starts_and_goals_off_land() {
    let spec = CoastalSpec::with_targets(2).with_behaviour(TargetBehaviour::Colregs);
    for index in 0..12 {
        let scenario = coastal(&spec, 21, index).expect("generated");
        assert_eq!(scenario, coastal(&spec, 21, index).expect("again"));
        // Round trip through the file format validates again.
        let text = scenario.to_ron_string().expect("written");
        Scenario::from_ron_str(&text, "<round trip>").expect("valid");
        // Independently of the chart: ownship's start and goal are the
        // planner's land clearance from every polygon, each target's start
        // the judged clearance.
        let polygons = polygons_m(&scenario.land);
        let planner_m = scenario.land_clearance_m() + 0.5 * scenario.ownship.length_m;
        let own = scenario.ownship_state().position_m;
        for point in [own, scenario.ownship_goal_m()] {
            for polygon in &polygons {
                let distance_m = Euclidean.distance(&Point::new(point.x, point.y), polygon);
                assert!(distance_m >= planner_m, "{}: {distance_m}", scenario.name);
            }
        }
        for target in &scenario.targets {
            let start = target.state().position_m;
            for polygon in &polygons {
                let distance_m = Euclidean.distance(&Point::new(start.x, start.y), polygon);
                assert!(
                    distance_m >= scenario.land_clearance_m(),
                    "{}: {distance_m}",
                    scenario.name
                );
            }
        }
    }
    assert_ne!(
        coastal(&spec, 21, 0).expect("generated").land,
        coastal(&spec, 22, 0).expect("generated").land
    );
}
