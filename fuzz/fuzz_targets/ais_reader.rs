//! Arbitrary bytes, read as UTF-8 (lossily), as an AIS log: `read_log` must
//! count every line and never panic; importing with the first vessel seen as
//! ownship must return a scenario or an error, never panic, and a scenario it
//! returns must survive the conversions the CLI applies to it.
#![no_main]

use libfuzzer_sys::fuzz_target;
use vorrt_ais::{ImportOptions, build_scenario, read_log};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let log = read_log(&text);
    assert!(log.counts.skipped() + log.counts.empty <= log.counts.lines);
    let Some(&mmsi) = log.vessels.keys().next() else {
        return;
    };
    let options = ImportOptions {
        log_name: "fuzz.nmea".into(),
        ownship_mmsi: mmsi,
        goal_lat_lon: (50.3, -0.8),
        at_unix_s: None,
        range_nm: 12.0,
    };
    if let Ok(import) = build_scenario(&log, &options) {
        let _ = import.scenario.planning_problem();
        let _ = import.scenario.to_ron_string();
    }
});
