//! Micro-benchmarks of the geometric and COLREGs primitives the planner calls
//! for every sample: CPA (unbounded and over a segment), velocity-obstacle
//! containment, encounter classification, the manoeuvre check and
//! `LinearTrack` prediction.
//!
//! Run with `cargo bench --bench geometry`; see `docs/performance.md`.

// criterion_group! and criterion_main! generate undocumented public functions.
#![allow(missing_docs)]

use criterion::{Criterion, black_box, criterion_group, criterion_main};
use glam::DVec2;
use std::time::Duration;
use vorrt::colregs::{
    Encounter, EncounterLatch, RuleParameters, VesselState, check_maneuver, classify,
};
use vorrt::geometry::cpa::{closest_point_of_approach, closest_point_of_approach_within};
use vorrt::geometry::velocity_obstacle::VelocityObstacle;
use vorrt::jfs::TargetState;

/// A fixed spread of (ownship, target) pairs covering every encounter type, so
/// that the branchy functions are not measured on one lucky path only.
fn pairs() -> Vec<(VesselState, VesselState)> {
    let own = VesselState::new(DVec2::ZERO, 0.0, 6.0, 100.0);
    (0..16)
        .map(|i| {
            let bearing = f64::from(i) * std::f64::consts::TAU / 16.0;
            let range = 2000.0 + 250.0 * f64::from(i);
            let position = DVec2::new(bearing.sin(), bearing.cos()) * range;
            // Heading back toward ownship, slightly off, at a speed that varies.
            let course = bearing + std::f64::consts::PI + 0.1 * f64::from(i % 3);
            let speed = 3.0 + 0.5 * f64::from(i % 7);
            (own, VesselState::new(position, course, speed, 150.0))
        })
        .collect()
}

fn bench_cpa(c: &mut Criterion) {
    let pairs = pairs();
    c.bench_function("geometry/cpa_unbounded", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (own, target) in &pairs {
                sum += closest_point_of_approach(
                    black_box(own.position_m),
                    black_box(own.velocity_mps()),
                    black_box(target.position_m),
                    black_box(target.velocity_mps()),
                )
                .distance_m;
            }
            sum
        });
    });
    c.bench_function("geometry/cpa_segment", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for (own, target) in &pairs {
                sum += closest_point_of_approach_within(
                    black_box(own.position_m),
                    black_box(own.velocity_mps()),
                    black_box(target.position_m),
                    black_box(target.velocity_mps()),
                    black_box(100.0 / 6.0),
                )
                .distance_m;
            }
            sum
        });
    });
}

fn bench_velocity_obstacle(c: &mut Criterion) {
    let pairs = pairs();
    let obstacles: Vec<(VelocityObstacle, DVec2)> = pairs
        .iter()
        .map(|(own, target)| {
            (
                VelocityObstacle::new(
                    own.position_m,
                    target.position_m,
                    target.velocity_mps(),
                    200.0,
                ),
                own.velocity_mps(),
            )
        })
        .collect();
    c.bench_function("geometry/vo_build", |b| {
        b.iter(|| {
            let mut inside = 0u32;
            for (own, target) in &pairs {
                let vo = VelocityObstacle::new(
                    black_box(own.position_m),
                    black_box(target.position_m),
                    black_box(target.velocity_mps()),
                    black_box(200.0),
                );
                inside += u32::from(vo.overlapping);
            }
            inside
        });
    });
    c.bench_function("geometry/vo_contains", |b| {
        b.iter(|| {
            let mut inside = 0u32;
            for (vo, velocity) in &obstacles {
                inside += u32::from(black_box(vo).contains(black_box(*velocity)));
            }
            inside
        });
    });
    c.bench_function("geometry/vo_contains_by_ray", |b| {
        b.iter(|| {
            let mut inside = 0u32;
            for (vo, velocity) in &obstacles {
                inside += u32::from(black_box(vo).contains_by_ray(black_box(*velocity)));
            }
            inside
        });
    });
}

fn bench_colregs(c: &mut Criterion) {
    let pairs = pairs();
    let rules = RuleParameters::default();
    c.bench_function("colregs/classify", |b| {
        b.iter(|| {
            let mut give_way = 0u32;
            for (own, target) in &pairs {
                give_way += u32::from(
                    classify(black_box(own), black_box(target), black_box(&rules))
                        == Encounter::CrossingGiveWay,
                );
            }
            give_way
        });
    });
    let latches: Vec<EncounterLatch> = pairs
        .iter()
        .map(|(own, target)| EncounterLatch::new(classify(own, target, &rules), own, 0.0))
        .collect();
    let candidates: Vec<f64> = (-3..=3).map(|k| f64::from(k) * 0.25).collect();
    c.bench_function("colregs/check_maneuver", |b| {
        b.iter(|| {
            let mut allowed = 0u32;
            for ((own, target), latch) in pairs.iter().zip(&latches) {
                for course in &candidates {
                    allowed += u32::from(
                        check_maneuver(
                            black_box(latch),
                            black_box(own.position_m),
                            black_box(*course),
                            black_box(own.speed_mps),
                            black_box(target),
                            black_box(&rules),
                        )
                        .is_ok(),
                    );
                }
            }
            allowed
        });
    });
}

fn bench_prediction(c: &mut Criterion) {
    let pairs = pairs();
    let targets: Vec<TargetState> = pairs
        .iter()
        .enumerate()
        .map(|(i, (_, target))| {
            if i % 2 == 0 {
                TargetState::constant_velocity(*target)
            } else {
                let north_m = 500.0 * f64::from(u32::try_from(i).expect("a few pairs"));
                TargetState::toward_goal(*target, DVec2::new(-8000.0, north_m))
            }
        })
        .collect();
    c.bench_function("jfs/track_build", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for target in &targets {
                sum += black_box(target).track().moving_for_s.min(1e9);
            }
            sum
        });
    });
    let tracks: Vec<_> = targets.iter().map(TargetState::track).collect();
    c.bench_function("jfs/track_state_at", |b| {
        b.iter(|| {
            let mut sum = DVec2::ZERO;
            for track in &tracks {
                sum += black_box(track).state_at(black_box(1234.5)).position_m;
            }
            sum
        });
    });
    c.bench_function("jfs/target_predict", |b| {
        b.iter(|| {
            let mut sum = DVec2::ZERO;
            for target in &targets {
                sum += black_box(target)
                    .predict(black_box(1234.5))
                    .vessel
                    .position_m;
            }
            sum
        });
    });
}

fn config() -> Criterion {
    // Each iteration is well under a microsecond: short runs suffice.
    Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_cpa, bench_velocity_obstacle, bench_colregs, bench_prediction
}
criterion_main!(benches);
