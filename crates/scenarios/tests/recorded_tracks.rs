//! A replay scenario on disk (decision 40): the scenario file names its
//! tracks file, `Scenario::load` reads it beside the scenario, and a
//! `Recorded` target follows its track in the closed loop.

use vorrt_scenarios::{Behaviour, ClosedLoop, Scenario};

const SCENARIO: &str = r#"Scenario(
    name: "replay",
    ownship: Vessel(name: "own", start_m: (0.0, 0.0), course_deg: 0.0, speed_kn: 12.0, length_m: 100.0, goal_m: (0.0, 3000.0)),
    targets: [
        Vessel(name: "T", start_m: (2000.0, 1500.0), course_deg: 270.0, speed_kn: 0.0, length_m: 50.0, behaviour: Recorded),
    ],
    recorded_tracks: "tracks/t.csv",
)
"#;

/// A fresh folder under the system's temporary one, for this test alone.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("vorrt-recorded-{name}-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("tracks")).expect("a scratch folder");
    dir
}

#[test]
fn load_reads_the_tracks_beside_the_scenario_and_the_target_follows_them() {
    let dir = scratch("follow");
    std::fs::write(dir.join("replay.ron"), SCENARIO).unwrap();
    std::fs::write(
        dir.join("tracks/t.csv"),
        "vessel,time_s,east_m,north_m,course_deg,speed_kn\nT,0,2000,1500,270,0\nT,100,1900,1500,270,2\n",
    )
    .unwrap();
    let scenario = Scenario::load(&dir.join("replay.ron")).expect("loads");
    assert_eq!(scenario.targets[0].behaviour, Behaviour::Recorded);
    let track = scenario.recorded.track("T").expect("T's track");
    assert_eq!(track.len(), 2);
    assert!(
        (track[0].vessel.length_m - 50.0).abs() < 1e-12,
        "its length from the scenario"
    );
    let mut run = ClosedLoop::new(&scenario, 1).expect("a run");
    for _ in 0..10 {
        run.step();
    }
    // At 50 s, half way between the two recorded states.
    let target = run.state().targets[0];
    assert!((target.position_m.x - 1950.0).abs() < 1e-9, "{target:?}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn a_missing_file_or_track_is_named() {
    let dir = scratch("missing");
    let path = dir.join("replay.ron");
    std::fs::write(&path, SCENARIO).unwrap();
    let error = Scenario::load(&path)
        .expect_err("no tracks file")
        .to_string();
    assert!(error.contains("t.csv"), "{error}");
    std::fs::write(
        dir.join("tracks/t.csv"),
        "vessel,time_s,east_m,north_m\nU,0,0,0\n",
    )
    .unwrap();
    let error = Scenario::load(&path)
        .expect_err("no track of T")
        .to_string();
    assert!(
        error.contains("targets[0] \"T\".behaviour is Recorded, but")
            && error.contains("has no rows with vessel \"T\""),
        "{error}"
    );
    // Without a tracks file named, a Recorded target is refused at once.
    let without = SCENARIO.replace("    recorded_tracks: \"tracks/t.csv\",\n", "");
    let error = Scenario::from_ron_str(&without, "x.ron")
        .expect_err("no file named")
        .to_string();
    assert!(error.contains("names no recorded_tracks file"), "{error}");
    // Parsed from text, the tracks are not read: a run is refused, not
    // sailed with the target standing still.
    let parsed = Scenario::from_ron_str(SCENARIO, "x.ron").expect("valid text");
    let error = ClosedLoop::new(&parsed, 1)
        .expect_err("no track loaded")
        .to_string();
    assert!(error.contains("Scenario::load reads them"), "{error}");
    std::fs::remove_dir_all(dir).ok();
}
