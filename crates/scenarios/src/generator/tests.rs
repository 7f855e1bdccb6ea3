//! Unit tests of the generator.

use super::*;
use rand_core::RngCore;

#[test]
fn streams_differ_per_index_and_repeat() {
    let a = scenario_stream(1, 0).next_u64();
    assert_eq!(a, scenario_stream(1, 0).next_u64());
    assert_ne!(a, scenario_stream(1, 1).next_u64());
    assert_ne!(a, scenario_stream(2, 0).next_u64());
}

#[test]
fn mix_with_one_weight_draws_only_that() {
    let mix = EncounterMix {
        head_on: 0.0,
        crossing_give_way: 0.0,
        crossing_stand_on: 0.0,
        overtaking: 2.0,
        being_overtaken: 0.0,
    };
    let mut rng = scenario_stream(3, 3);
    assert!((0..100).all(|_| mix.draw(&mut rng) == Encounter::Overtaking));
}

#[test]
fn bad_specs_are_refused() {
    assert!(matches!(
        open_sea(&OpenSeaSpec::with_targets(0), 1, 0),
        Err(GeneratorError::InvalidSpec(_))
    ));
    assert!(matches!(
        open_sea(&OpenSeaSpec::with_targets(MAX_GENERATED_TARGETS + 1), 1, 0),
        Err(GeneratorError::InvalidSpec(_))
    ));
    // As many as a scenario may hold (issue 24: many vessels).
    assert_eq!(MAX_GENERATED_TARGETS, crate::MAX_TARGETS);
    let most = open_sea(&OpenSeaSpec::with_targets(MAX_GENERATED_TARGETS), 1, 0).expect("valid");
    assert_eq!(most.targets.len(), MAX_GENERATED_TARGETS);
    let mut spec = OpenSeaSpec::with_targets(2);
    spec.mix = EncounterMix {
        head_on: 0.0,
        crossing_give_way: 0.0,
        crossing_stand_on: 0.0,
        overtaking: 0.0,
        being_overtaken: 0.0,
    };
    assert!(open_sea(&spec, 1, 0).is_err());
    assert!(tss(&TssSpec::with_density(f64::NAN), 1, 0).is_err());
}

#[test]
fn behaviour_names_parse() {
    for name in ["constant", "colregs", "noisy", "sudden-turn"] {
        assert_eq!(TargetBehaviour::from_name(name).unwrap().name(), name);
    }
    assert!(TargetBehaviour::from_name("wild").is_err());
}
