//! A bundled encounter, measured and classified: for each of three targets it
//! prints the range, both relative bearings, the closest point of approach,
//! whether there is a risk of collision, the encounter type (rules 13-15) and
//! ownship's role.
//!
//! Run with `cargo run --release --example encounter`.
#![allow(clippy::print_stdout)]

use vorrt::colregs::{RuleParameters, VesselState, assess_risk, classify};
use vorrt::geometry::{DVec2, units};

/// Ownship's and the targets' length overall, metres.
const LENGTH_M: f64 = 100.0;

/// A vessel from mariners' units: position in nautical miles east and north
/// of the origin, course in degrees, speed in knots.
fn vessel(east_nm: f64, north_nm: f64, course_deg: f64, speed_kn: f64) -> VesselState {
    VesselState::new(
        DVec2::new(
            units::nautical_miles_to_m(east_nm),
            units::nautical_miles_to_m(north_nm),
        ),
        course_deg.to_radians(),
        units::knots_to_mps(speed_kn),
        LENGTH_M,
    )
}

fn main() {
    let parameters = RuleParameters::default();
    let ownship = vessel(0.0, 0.0, 0.0, 12.0);
    let targets = [
        // 3 nm east, 3 nm north, heading west at 12 kn: on a collision course.
        ("crossing", vessel(3.0, 3.0, 270.0, 12.0)),
        // 4.5 nm dead ahead, heading south at 12 kn.
        ("meeting", vessel(0.0, 4.5, 180.0, 12.0)),
        // 2 nm ahead and 0.1 nm to starboard, heading north at 6 kn.
        ("slower ahead", vessel(0.1, 2.0, 0.0, 6.0)),
    ];

    println!("ownship: at the origin, course 000 deg, 12.0 kn, length {LENGTH_M} m");
    println!(
        "risk of collision: range < {:.1} nm (MTD), d_cpa < {:.1} nm, t_cpa > 0",
        units::m_to_nautical_miles(parameters.mtd_m),
        units::m_to_nautical_miles(parameters.risk_cpa_m),
    );
    println!();
    println!(
        "target         range(nm)  brg(deg)  rev(deg)  t_cpa(min)  d_cpa(nm)  risk  encounter          role"
    );
    for (name, target) in &targets {
        let risk = assess_risk(&ownship, target, &parameters);
        let encounter = classify(&ownship, target, &parameters);
        println!(
            "{:<13} {:>10.2} {:>9.1} {:>9.1} {:>11.1} {:>10.2} {:>5}  {:<18} {}",
            name,
            units::m_to_nautical_miles(risk.range_m),
            ownship.bearing_to(target).to_degrees(),
            target.bearing_to(&ownship).to_degrees(),
            risk.cpa.time_s / 60.0,
            units::m_to_nautical_miles(risk.cpa.distance_m),
            if risk.at_risk { "yes" } else { "no" },
            encounter.name(),
            encounter.role().name(),
        );
    }
    println!();
    println!(
        "brg: relative bearing of the target from ownship (0 = dead ahead, 90 = starboard beam)"
    );
    println!("rev: relative bearing of ownship from the target");
}
