//! `replay.html`: one self-contained page that replays a run (decision 35).
//!
//! The page is the template `replay.html` with the script `replay.js` and
//! the run's data ([`data::ReplayData`], inline JSON) put in; no network,
//! no library: it opens from disk. `vorrt simulate --out`, `vorrt judge
//! --out` and every run of `vorrt demo` write it beside `report.json`.

pub(crate) mod data;
pub(crate) mod findings;
pub(crate) mod graticule;

use crate::error::CliError;
use crate::report::Report;
use data::ReplayData;
use std::path::Path;
use vorrt_scenarios::{Evaluation, Scenario, SimulationRecord};

/// The file the replay is written to.
pub(crate) const REPLAY_HTML: &str = "replay.html";

/// The page's template: `{{TITLE}}`, `{{SCRIPT}}` and `{{DATA}}` are filled in.
const TEMPLATE: &str = include_str!("replay.html");

/// The page's script.
const SCRIPT: &str = include_str!("replay.js");

/// `json` made safe inside a `<script>` element: `<`, `>` and `&` as JSON
/// escapes (`\u003c`...), so that no `</script>` or `<!--` in a name can end
/// or change the element, and the text still parses as the same JSON
/// (HTML 5.2, 4.12.1.3 "Restrictions for contents of script elements").
#[must_use]
pub(crate) fn script_safe_json(json: &str) -> String {
    let mut safe = String::with_capacity(json.len());
    for c in json.chars() {
        match c {
            '<' => safe.push_str("\\u003c"),
            '>' => safe.push_str("\\u003e"),
            '&' => safe.push_str("\\u0026"),
            // Line and paragraph separators, which old JavaScript parsers
            // took for line ends inside strings.
            '\u{2028}' => safe.push_str("\\u2028"),
            '\u{2029}' => safe.push_str("\\u2029"),
            _ => safe.push(c),
        }
    }
    safe
}

/// `text` as HTML text: `&`, `<`, `>`, `"` and `'` as character references.
#[must_use]
pub(crate) fn escape_html(text: &str) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => escaped.push_str("&amp;"),
            '<' => escaped.push_str("&lt;"),
            '>' => escaped.push_str("&gt;"),
            '"' => escaped.push_str("&quot;"),
            '\'' => escaped.push_str("&#39;"),
            _ => escaped.push(c),
        }
    }
    escaped
}

/// `template` with every `{{KEY}}` of `values` replaced in one pass, so that
/// no value is searched for the keys of another.
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut page =
        String::with_capacity(template.len() + values.iter().map(|(_, v)| v.len()).sum::<usize>());
    let mut rest = template;
    while let Some(start) = rest.find("{{") {
        let Some(length) = rest[start..].find("}}") else {
            break;
        };
        let key = &rest[start + 2..start + length];
        page.push_str(&rest[..start]);
        match values.iter().find(|(name, _)| *name == key) {
            Some((_, value)) => page.push_str(value),
            None => page.push_str(&rest[start..start + length + 2]),
        }
        rest = &rest[start + length + 2..];
    }
    page.push_str(rest);
    page
}

/// The page replaying `data`.
///
/// # Errors
/// [`CliError::Output`] if the data cannot be written as JSON (a number
/// that is not finite is written `null`, so this does not happen).
pub(crate) fn page(data: &ReplayData) -> Result<String, CliError> {
    let json = serde_json::to_string(data)
        .map_err(|error| CliError::Output(format!("cannot write the replay data: {error}")))?;
    let title = escape_html(&format!("{} - vorrt replay", data.scenario));
    Ok(fill(
        TEMPLATE,
        &[
            ("TITLE", &title),
            ("SCRIPT", SCRIPT),
            ("DATA", &script_safe_json(&json)),
        ],
    ))
}

/// Writes `replay.html` of the run of `scenario` recorded in `record`,
/// judged in `evaluation` and reported in `report` into `dir`.
///
/// # Errors
/// [`CliError::Output`] when the file cannot be written.
pub(crate) fn write_replay(
    scenario: &Scenario,
    record: &SimulationRecord,
    evaluation: &Evaluation,
    report: &Report,
    dir: &Path,
) -> Result<(), CliError> {
    let text = page(&ReplayData::new(scenario, record, evaluation, report))?;
    let path = dir.join(REPLAY_HTML);
    std::fs::write(&path, text)
        .map_err(|error| CliError::Output(format!("cannot write {}: {error}", path.display())))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_script_cannot_end_its_element_early() {
        assert!(!SCRIPT.to_ascii_lowercase().contains("</script"));
        assert!(!SCRIPT.contains("{{"), "the script holds no template key");
        for key in ["{{TITLE}}", "{{SCRIPT}}", "{{DATA}}"] {
            assert_eq!(TEMPLATE.matches(key).count(), 1, "{key}");
        }
    }

    #[test]
    fn escape_html_escapes_markup() {
        assert_eq!(
            escape_html("a</b> & \"c\" 'd'"),
            "a&lt;/b&gt; &amp; &quot;c&quot; &#39;d&#39;"
        );
    }

    #[test]
    fn script_safe_json_parses_as_the_same_value() {
        let json = serde_json::json!({"name": "a</script><!--b&c\u{2028}"}).to_string();
        let safe = script_safe_json(&json);
        assert!(!safe.contains('<') && !safe.contains('>') && !safe.contains('&'));
        let back: serde_json::Value = serde_json::from_str(&safe).unwrap();
        assert_eq!(back["name"], "a</script><!--b&c\u{2028}");
    }

    #[test]
    fn fill_replaces_each_key_once_and_leaves_values_alone() {
        let page = fill(
            "<{{A}}|{{B}}|{{C}}>",
            &[("A", "{{B}}"), ("B", "b"), ("C", "}}")],
        );
        assert_eq!(page, "<{{B}}|b|}}>");
        assert_eq!(fill("{{unknown}} {{", &[]), "{{unknown}} {{");
    }

    #[test]
    fn the_page_carries_the_run_and_its_findings() {
        let scenario = crate::fixtures::load(
            crate::fixtures::BUNDLED
                .iter()
                .find(|fixture| fixture.stem() == "imazu_01")
                .expect("imazu_01 is bundled"),
        )
        .unwrap();
        let run = crate::run::run_scenario(&scenario, 1).unwrap();
        let data = ReplayData::new(&scenario, &run.record, &run.evaluation, &run.report);
        assert_eq!(data.times_s, run.record.times_s);
        assert_eq!(data.vessels.len(), 1 + scenario.targets.len());
        let findings: usize = run.report.targets.iter().map(|t| t.findings.len()).sum();
        assert_eq!(
            data.findings.len(),
            findings + run.report.path_quality.findings.len()
        );
        let html = page(&data).unwrap();
        assert!(html.contains("window.vorrtReplay"));
        assert!(!html.contains("{{DATA}}"));
    }

    /// The page draws the land, no-go areas and separation zones the run
    /// kept: the Dover crossing has its Natural Earth coast and its
    /// separation zone in the page's data.
    #[test]
    fn the_page_carries_land_and_the_separation_zone() {
        let fixture = crate::fixtures::BUNDLED
            .iter()
            .find(|fixture| fixture.stem() == "dover_tss_crossing")
            .expect("bundled");
        let scenario = crate::fixtures::load(fixture).unwrap();
        let run = crate::run::run_scenario(&scenario, 1).unwrap();
        let data = ReplayData::new(&scenario, &run.record, &run.evaluation, &run.report);
        assert_eq!(data.land.len(), scenario.land_areas().count());
        assert!(!data.land.is_empty());
        assert!(data.land.iter().all(|polygon| polygon[0].len() >= 3));
        assert_eq!(data.separation_zones.len(), 1);
        assert_eq!(data.separation_zones[0][0].len(), 4);
        assert!(data.no_go.is_empty());
    }
}
