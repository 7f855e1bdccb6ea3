//! Robustness (issue 7): whatever a scenario holds — NaN, infinities,
//! negative or huge numbers, missing or doubled positions, too many targets —
//! and whatever text is given to the parser, validation and conversion return
//! `Ok` or a typed [`ScenarioError`], never panic.
//!
//! The cases are drawn from a seeded `ChaCha8` stream (the crate's own random
//! source; no extra dev-dependency), 256 per property, so a failure is
//! reproducible from the case number printed with it.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, missing_docs)]

use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use std::time::Instant;
use vorrt_planner::{PlannerError, PlanningProblem};
use vorrt_scenarios::{
    Behaviour, Lane, MAX_TARGETS, PlannerSettings, ProjectedPositions, Rule10Settings, Scenario,
    ScenarioError, SeparationZoneSpec, SimulationSettings, VesselSpec,
};

const CASES: u64 = 256;

/// A small random source with the helpers the generators need.
struct Gen(ChaCha8Rng);

impl Gen {
    fn new(case: u64) -> Self {
        Self(ChaCha8Rng::seed_from_u64(0x7_0b05 ^ case))
    }

    fn below(&mut self, n: u64) -> u64 {
        self.0.next_u64() % n.max(1)
    }

    /// [`Gen::below`] as an index.
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the tests run on 64-bit targets, where `u64` fits `usize`"
    )]
    fn below_usize(&mut self, n: u64) -> usize {
        self.below(n) as usize
    }

    fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }

    #[expect(clippy::cast_precision_loss, reason = "53-bit values, exact in f64")]
    fn unit(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Any f64: special values, plausible ones, huge ones or raw bits.
    fn any_f64(&mut self) -> f64 {
        const SPECIAL: [f64; 16] = [
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            -1.0,
            1.0,
            1e308,
            -1e308,
            f64::MAX,
            f64::MIN,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            1e-300,
            360.0,
        ];
        match self.below(4) {
            0 => SPECIAL[self.below_usize(SPECIAL.len() as u64)],
            1 => f64::from_bits(self.0.next_u64()),
            2 => (self.unit() - 0.5) * 1e12,
            _ => (self.unit() - 0.5) * 40.0,
        }
    }

    /// A plausible number most of the time, any f64 otherwise.
    fn mostly(&mut self, low: f64, high: f64) -> f64 {
        if self.chance(80) {
            low + self.unit() * (high - low)
        } else {
            self.any_f64()
        }
    }

    fn maybe_pair(&mut self, present: u64, low: f64, high: f64) -> Option<(f64, f64)> {
        self.chance(present)
            .then(|| (self.mostly(low, high), self.mostly(low, high)))
    }

    fn name(&mut self, index: usize) -> String {
        match self.below(10) {
            0 => String::new(),
            1 => "   ".into(),
            2 => "dup".into(),
            3 => "ownship".into(),
            _ => format!("v{index}"),
        }
    }

    fn behaviour(&mut self) -> Behaviour {
        match self.below(5) {
            0 => Behaviour::ConstantToGoal,
            1 => Behaviour::ConstantVelocity,
            2 => Behaviour::Colregs,
            3 => Behaviour::Noisy {
                course_sigma_deg: self.mostly(0.0, 30.0),
                speed_sigma_kn: self.mostly(0.0, 3.0),
            },
            _ => Behaviour::SuddenTurn {
                at_s: self.mostly(0.0, 2000.0),
                turn_deg: self.mostly(-180.0, 180.0),
            },
        }
    }

    fn vessel(&mut self, index: usize) -> VesselSpec {
        VesselSpec {
            name: self.name(index),
            start_nm: self.maybe_pair(85, -5.0, 5.0),
            start_m: self.maybe_pair(15, -9000.0, 9000.0),
            course_deg: self.mostly(-720.0, 720.0),
            speed_kn: self.mostly(-2.0, 30.0),
            length_m: self.mostly(-10.0, 400.0),
            goal_nm: self.maybe_pair(70, -5.0, 5.0),
            goal_m: self.maybe_pair(10, -9000.0, 9000.0),
            behaviour: self.behaviour(),
            start_lat_lon: None,
            goal_lat_lon: None,
            mmsi: None,
            max_turn_rate_deg_s: self.opt(-1.0, 5.0),
            projected: ProjectedPositions::default(),
        }
    }

    fn opt(&mut self, low: f64, high: f64) -> Option<f64> {
        self.chance(25).then(|| self.mostly(low, high))
    }

    fn opt_count(&mut self) -> Option<usize> {
        self.chance(25).then(|| match self.below(4) {
            0 => 0,
            1 => usize::MAX,
            2 => self.below_usize(1 << 40),
            _ => self.below_usize(500),
        })
    }

    fn planner(&mut self) -> PlannerSettings {
        PlannerSettings {
            clearance_m: self.opt(0.0, 500.0),
            step_m: self.opt(0.0, 300.0),
            goal_tolerance_m: self.opt(0.0, 300.0),
            goal_bias: self.opt(-0.5, 1.5),
            phase_two_goal_bias: self.opt(-0.5, 1.5),
            nodes_per_phase: self.opt_count(),
            samples_per_phase: self.opt_count(),
            max_restarts: self.opt_count(),
            max_turn_per_step_deg: self.opt(-10.0, 200.0),
            sampling_margin_nm: self.opt(-1.0, 5.0),
            lookahead_s: self.opt(-10.0, 3000.0),
            time_budget_s: self.opt(-1.0, 10.0),
            mtd_nm: self.opt(-1.0, 10.0),
            risk_cpa_nm: self.opt(-1.0, 3.0),
            head_on_half_width_deg: self.opt(-10.0, 100.0),
            abaft_beam_deg: self.opt(-10.0, 200.0),
            passed_angle_deg: self.opt(-10.0, 200.0),
            turn_tolerance_deg: self.opt(-10.0, 50.0),
            stand_on_course_tolerance_deg: self.opt(-10.0, 50.0),
            stand_on_speed_tolerance_kn: self.opt(-1.0, 5.0),
            stand_on_action_range_nm: self.opt(-1.0, 5.0),
            apparent_turn_deg: self.opt(-10.0, 100.0),
            ..PlannerSettings::default()
        }
    }

    fn scenario(&mut self) -> Scenario {
        let targets = match self.below(20) {
            0 => MAX_TARGETS + 1 + self.below_usize(4),
            1 => 0,
            _ => self.below_usize(5),
        };
        let lanes = (0..self.below_usize(3))
            .map(|index| {
                Lane::new_nm(
                    self.name(index),
                    (self.mostly(-5.0, 5.0), self.mostly(-5.0, 5.0)),
                    (self.mostly(-5.0, 5.0), self.mostly(-5.0, 5.0)),
                    self.mostly(-1.0, 3.0),
                )
            })
            .collect();
        let zones = if self.chance(20) {
            self.below_usize(2)
        } else {
            0
        };
        let separation_zones = (0..zones)
            .map(|index| {
                let vertices = (0..self.below_usize(5))
                    .map(|_| (self.mostly(-5.0, 5.0), self.mostly(-5.0, 5.0)))
                    .collect();
                SeparationZoneSpec::new_nm(self.name(index), vertices)
            })
            .collect();
        Scenario {
            name: if self.chance(5) {
                String::new()
            } else {
                "fuzzed".into()
            },
            description: None,
            ownship: self.vessel(usize::MAX),
            targets: (0..targets).map(|index| self.vessel(index)).collect(),
            planner: if self.chance(50) {
                self.planner()
            } else {
                PlannerSettings::default()
            },
            simulation: SimulationSettings {
                time_step_s: self.mostly(0.0, 20.0),
                max_duration_s: self.opt(0.0, 1e5),
                replan_deviation_m: self.mostly(0.0, 200.0),
            },
            lanes,
            land: Vec::new(),
            no_go: Vec::new(),
            land_geojson: None,
            land_clearance_m: None,
            geojson_land: Vec::new(),
            base_dir: None,
            separation_zones,
            rule10: Rule10Settings {
                crossing_tolerance_deg: if self.chance(10) {
                    self.opt(-10.0, 60.0)
                } else {
                    None
                },
                flow_tolerance_deg: None,
            },
            seed: Some(self.0.next_u64()),
            start_time: None,
            source: "generated.ron".into(),
            recorded_tracks: None,
            recorded: vorrt_scenarios::RecordedTracks::default(),
        }
    }
}

fn assert_names_the_file(error: &ScenarioError, case: u64) {
    let message = error.to_string();
    assert!(message.contains("generated.ron"), "case {case}: {message}");
    if let ScenarioError::Invalid { field, .. } = error {
        assert!(!field.is_empty(), "case {case}: {message}");
    }
}

fn check_problem(problem: &PlanningProblem, case: u64) {
    match problem.validate() {
        Ok(()) => {}
        Err(PlannerError::InvalidProblem { field, .. }) => {
            assert!(!field.is_empty(), "case {case}");
        }
        Err(other) => panic!("case {case}: unexpected error {other}"),
    }
}

#[test]
fn arbitrary_scenario_values_validate_or_name_a_field() {
    let mut valid = 0;
    for case in 0..CASES {
        let mut scenario = Gen::new(case).scenario();
        // Conversions of the unvalidated scenario must not panic either.
        check_problem(&scenario.planning_problem(), case);
        let _ = scenario.max_duration_s();
        match scenario.planner_config() {
            Ok(config) => config.validate().expect("planner_config validates"),
            Err(error) => assert_names_the_file(&error, case),
        }
        match scenario.validate() {
            Ok(()) => {
                valid += 1;
                // A valid scenario converts to a valid problem and config,
                // and survives a round trip through RON.
                scenario
                    .planning_problem()
                    .validate()
                    .unwrap_or_else(|error| panic!("case {case}: {error}"));
                scenario.planner_config().expect("valid config");
                assert!(scenario.max_duration_s().is_finite(), "case {case}");
                let text = scenario.to_ron_string().expect("writes");
                let back = Scenario::from_ron_str(&text, "generated.ron")
                    .unwrap_or_else(|error| panic!("case {case}: {error}\n{text}"));
                assert_eq!(back, scenario, "case {case}");
            }
            Err(error) => {
                assert!(
                    matches!(error, ScenarioError::Invalid { .. }),
                    "case {case}: {error}"
                );
                assert_names_the_file(&error, case);
            }
        }
    }
    // The generator is not so hostile that nothing ever passes.
    assert!(valid > 0, "no generated scenario was valid");
}

#[test]
#[expect(clippy::cast_precision_loss, reason = "target indices, far below 2^52")]
fn too_many_targets_are_refused_by_name() {
    let mut scenario = Gen::new(1).scenario();
    scenario.ownship =
        VesselSpec::new("ownship", (0.0, -3.0), 0.0, 12.0, 100.0).with_goal_nm((0.0, 3.0));
    scenario.planner = PlannerSettings::default();
    scenario.targets = (0..=MAX_TARGETS)
        .map(|index| {
            VesselSpec::new(
                format!("TS{index}"),
                (index as f64 * 0.01, 1.0),
                0.0,
                5.0,
                50.0,
            )
        })
        .collect();
    let error = scenario.validate().expect_err("too many targets");
    assert_eq!(error.field(), Some("targets"), "{error}");
}

fn fixture_texts() -> Vec<String> {
    let root = vorrt_scenarios::bundled_fixtures_dir();
    ["paper", "imazu"]
        .iter()
        .flat_map(|dir| vorrt_scenarios::load_dir(&root.join(dir)).expect("fixtures load"))
        .map(|(path, _)| std::fs::read_to_string(path).unwrap())
        .collect()
}

/// Tokens spliced into RON text: delimiters, keywords, special numbers.
const TOKENS: [&str; 24] = [
    "(",
    ")",
    "[",
    "]",
    ",",
    ":",
    "\"",
    "NaN",
    "inf",
    "-inf",
    "1e999",
    "-0.0",
    "Some(",
    "None",
    "Vessel(",
    "//",
    "/*",
    "\\u{0}",
    "18446744073709551616",
    "-1",
    "r#\"",
    "'",
    "true",
    "\n",
];

/// A mutation of a real scenario file: truncated, bytes replaced, tokens
/// inserted, numbers replaced by special values, or pieces of two files mixed.
fn mutate(g: &mut Gen, texts: &[String]) -> String {
    let mut text: Vec<char> = texts[g.below_usize(texts.len() as u64)].chars().collect();
    for _ in 0..=g.below(6) {
        let at = g.below_usize(text.len() as u64 + 1);
        match g.below(6) {
            0 => text.truncate(at),
            1 => {
                if at < text.len() {
                    text[at] = char::from_u32(u32::try_from(g.below(0x3000)).unwrap())
                        .unwrap_or('\u{fffd}');
                }
            }
            2 => {
                let token = TOKENS[g.below_usize(TOKENS.len() as u64)];
                text.splice(at..at, token.chars());
            }
            3 => {
                let end = (at + g.below_usize(40)).min(text.len());
                text.drain(at..end);
            }
            4 => {
                // Replace the number starting at or after `at`.
                let start = text[at..]
                    .iter()
                    .position(char::is_ascii_digit)
                    .map(|offset| at + offset);
                if let Some(start) = start {
                    let end = text[start..]
                        .iter()
                        .position(|c| !(c.is_ascii_digit() || *c == '.'))
                        .map_or(text.len(), |offset| start + offset);
                    let value = format!("{:?}", g.any_f64());
                    text.splice(start..end, value.chars());
                }
            }
            _ => {
                let other: Vec<char> = texts[g.below_usize(texts.len() as u64)].chars().collect();
                let from = g.below_usize(other.len() as u64);
                text.splice(at..at, other[from..].iter().copied().take(200));
            }
        }
    }
    text.into_iter().collect()
}

#[test]
fn mutated_scenario_text_parses_or_errs() {
    let texts = fixture_texts();
    assert!(texts.len() >= 20);
    for case in 0..4 * CASES {
        let mut g = Gen::new(case);
        let text = mutate(&mut g, &texts);
        match Scenario::from_ron_str(&text, "generated.ron") {
            Ok(scenario) => check_problem(&scenario.planning_problem(), case),
            Err(ScenarioError::Syntax {
                file, line, column, ..
            }) => {
                assert_eq!(file, "generated.ron");
                assert!(line >= 1 && column >= 1, "case {case}: {line}:{column}");
            }
            Err(error) => assert_names_the_file(&error, case),
        }
    }
}

#[test]
fn random_text_parses_or_errs() {
    const ALPHABET: &[u8] =
        b"()[]{},:\"'. -+0123456789eEScenarioVesselnamestartgoal_nmNaNinf\n\t/*#r";
    for case in 0..CASES {
        let mut g = Gen::new(case);
        let length = g.below_usize(300);
        let text: String = (0..length)
            .map(|_| ALPHABET[g.below_usize(ALPHABET.len() as u64)] as char)
            .collect();
        let started = Instant::now();
        let result = Scenario::from_ron_str(&text, "generated.ron");
        assert!(started.elapsed().as_secs_f64() < 1.0, "case {case}");
        if let Err(error) = result {
            assert_names_the_file(&error, case);
        }
    }
}

#[test]
fn deeply_nested_text_is_an_error_not_a_stack_overflow() {
    for depth in [1_000, 100_000] {
        let text = format!("Scenario(name: {}{}", "(".repeat(depth), ")".repeat(depth));
        let error = Scenario::from_ron_str(&text, "generated.ron").expect_err("not a scenario");
        assert!(matches!(error, ScenarioError::Syntax { .. }), "{error}");
        let text = format!("Scenario(name: \"n\", targets: {}", "[".repeat(depth));
        Scenario::from_ron_str(&text, "generated.ron").expect_err("not a scenario");
    }
}
