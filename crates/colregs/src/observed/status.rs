//! What a vessel says it is doing: the AIS navigational status (ITU-R
//! M.1371-5, message types 1-3, field "navigational status"), and what the
//! rules make of it (rules 3, 18; decision 32).

use serde::{Deserialize, Serialize};

/// A vessel's navigational status as AIS reports it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NavigationalStatus {
    /// 0: under way using engine.
    UnderWayUsingEngine,
    /// 1: at anchor.
    AtAnchor,
    /// 2: not under command (rule 18(a)(i), 18(b)(i), 18(c)(i)).
    NotUnderCommand,
    /// 3: restricted in her ability to manoeuvre (rule 18(a)(ii)).
    RestrictedManoeuvrability,
    /// 4: constrained by her draught (rule 18(d)).
    ConstrainedByDraught,
    /// 5: moored.
    Moored,
    /// 6: aground.
    Aground,
    /// 7: engaged in fishing (rule 18(a)(iii), 18(b)(iii)).
    EngagedInFishing,
    /// 8: under way sailing (rule 18(a)(iv)).
    UnderWaySailing,
    /// 9-14: reserved or an AIS-SART; 15 is "not defined" (no status).
    Other,
}

impl NavigationalStatus {
    /// The status of an AIS code; `None` for 15 ("not defined", the default)
    /// and for codes above 15.
    ///
    /// ```
    /// use vorrt_colregs::observed::NavigationalStatus;
    /// assert_eq!(NavigationalStatus::from_ais(1), Some(NavigationalStatus::AtAnchor));
    /// assert_eq!(NavigationalStatus::from_ais(15), None);
    /// ```
    #[must_use]
    pub fn from_ais(code: u8) -> Option<Self> {
        Some(match code {
            0 => Self::UnderWayUsingEngine,
            1 => Self::AtAnchor,
            2 => Self::NotUnderCommand,
            3 => Self::RestrictedManoeuvrability,
            4 => Self::ConstrainedByDraught,
            5 => Self::Moored,
            6 => Self::Aground,
            7 => Self::EngagedInFishing,
            8 => Self::UnderWaySailing,
            9..=14 => Self::Other,
            _ => return None,
        })
    }

    /// Whether the vessel is not under way (rule 3(i): at anchor, made fast
    /// to the shore, or aground): a stationary obstacle to keep clear of,
    /// not a partner in a crossing, head-on or overtaking encounter.
    ///
    /// ```
    /// use vorrt_colregs::observed::NavigationalStatus;
    /// assert!(NavigationalStatus::Moored.is_at_rest());
    /// assert!(!NavigationalStatus::EngagedInFishing.is_at_rest());
    /// ```
    #[must_use]
    pub fn is_at_rest(self) -> bool {
        matches!(self, Self::AtAnchor | Self::Moored | Self::Aground)
    }

    /// The rule 18 responsibility a power-driven vessel under way has toward
    /// a vessel of this status, in words; `None` when rules 13-17 apply as
    /// between two power-driven vessels.
    ///
    /// ```
    /// use vorrt_colregs::observed::NavigationalStatus;
    /// assert!(NavigationalStatus::EngagedInFishing.rule_18().unwrap().contains("18(a)(iii)"));
    /// assert!(NavigationalStatus::UnderWayUsingEngine.rule_18().is_none());
    /// ```
    #[must_use]
    pub fn rule_18(self) -> Option<&'static str> {
        Some(match self {
            Self::NotUnderCommand => {
                "not under command: a power-driven vessel under way keeps out of her way (rule 18(a)(i))"
            }
            Self::RestrictedManoeuvrability => {
                "restricted in her ability to manoeuvre: a power-driven vessel under way keeps out of her way (rule 18(a)(ii))"
            }
            Self::EngagedInFishing => {
                "engaged in fishing: a power-driven vessel under way keeps out of her way (rule 18(a)(iii))"
            }
            Self::UnderWaySailing => {
                "a sailing vessel: a power-driven vessel under way keeps out of her way (rule 18(a)(iv)), unless overtaking (rule 13)"
            }
            Self::ConstrainedByDraught => {
                "constrained by her draught: other vessels avoid impeding her safe passage (rule 18(d))"
            }
            Self::AtAnchor | Self::Moored | Self::Aground => {
                "not under way (rule 3(i)): a stationary obstacle, kept clear of; no crossing, head-on or overtaking encounter"
            }
            Self::UnderWayUsingEngine | Self::Other => return None,
        })
    }

    /// A short name in snake case, as used in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::UnderWayUsingEngine => "under_way_using_engine",
            Self::AtAnchor => "at_anchor",
            Self::NotUnderCommand => "not_under_command",
            Self::RestrictedManoeuvrability => "restricted_manoeuvrability",
            Self::ConstrainedByDraught => "constrained_by_draught",
            Self::Moored => "moored",
            Self::Aground => "aground",
            Self::EngagedInFishing => "engaged_in_fishing",
            Self::UnderWaySailing => "under_way_sailing",
            Self::Other => "other",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_code_maps_and_names_are_distinct() {
        let statuses: Vec<_> = (0..=15).filter_map(NavigationalStatus::from_ais).collect();
        assert_eq!(statuses.len(), 15);
        let mut names: Vec<_> = statuses.iter().map(|s| s.name()).collect();
        names.dedup();
        assert_eq!(names.len(), 10);
        assert_eq!(NavigationalStatus::from_ais(200), None);
    }
}
