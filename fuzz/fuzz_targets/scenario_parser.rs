//! Arbitrary bytes, read as UTF-8 (lossily), into `Scenario::from_ron_str`:
//! it must return `Ok` or `Err`, never panic. An accepted scenario must also
//! survive the conversions the CLI applies to it.
#![no_main]

use libfuzzer_sys::fuzz_target;
use vorrt_scenarios::Scenario;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(scenario) = Scenario::from_ron_str(&text, "fuzz.ron") {
        // A scenario that validates must convert and re-serialise.
        let _ = scenario.planning_problem();
        let _ = scenario.planner_config();
        let _ = scenario.max_duration_s();
        let _ = scenario.to_ron_string();
    }
});
