//! `vorrt demo`: every bundled scenario run in parallel, each written as
//! `simulate` writes it, and an `index.html` showing them all.

use crate::console;
use crate::error::{CliError, ExitStatus};
use crate::fixtures::{self, BUNDLED};
use crate::report::Report;
use crate::run::{folder_name, run_scenario, seed_for, write_outputs};
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use vorrt_scenarios::{Scenario, load_dir};

/// The options of `vorrt demo`.
#[derive(Debug, Clone, Default)]
pub(crate) struct DemoOptions {
    /// Output folder.
    pub(crate) out: PathBuf,
    /// Seed for every scenario (else each scenario's own, else 1).
    pub(crate) seed: Option<u64>,
    /// Scenario folder (else the bundled fixtures).
    pub(crate) fixtures: Option<PathBuf>,
    /// Names or file stems to run (all when empty).
    pub(crate) only: Vec<String>,
}

/// One scenario to run.
#[derive(Debug, Clone)]
struct Entry {
    group: String,
    stem: String,
    scenario: Scenario,
}

impl Entry {
    /// The scenario's folder, relative to the output folder.
    fn folder(&self) -> PathBuf {
        Path::new(&self.group).join(&self.stem)
    }

    fn anchor(&self) -> String {
        format!("{}-{}", self.group, self.stem)
    }
}

/// How one scenario's run went.
#[derive(Debug)]
struct Outcome {
    entry: Entry,
    result: Result<Report, CliError>,
    /// The run reached its goal safely and obeyed COLREGs
    /// ([`crate::run::Run::status`]); false on error.
    passed: bool,
    wall_time_s: f64,
}

fn group_name(dir: &Path) -> String {
    dir.file_name().map_or_else(
        || "scenarios".to_owned(),
        |name| folder_name(&name.to_string_lossy()),
    )
}

fn load_group(dir: &Path, group: &str) -> Result<Vec<Entry>, CliError> {
    let loaded = load_dir(dir).map_err(|error| CliError::BadInput(error.to_string()))?;
    Ok(loaded
        .into_iter()
        .map(|(path, scenario)| Entry {
            group: group.to_owned(),
            stem: path.file_stem().map_or_else(
                || folder_name(&scenario.name),
                |stem| folder_name(&stem.to_string_lossy()),
            ),
            scenario,
        })
        .collect())
}

/// The bundled scenarios, from the copies embedded in the binary.
fn collect_bundled() -> Result<Vec<Entry>, CliError> {
    BUNDLED
        .iter()
        .map(|fixture| {
            Ok(Entry {
                group: fixture.group.to_owned(),
                stem: folder_name(fixture.stem()),
                scenario: fixtures::load(fixture)?,
            })
        })
        .collect()
}

/// The scenarios of `dir`: its own `*.ron` files, then those of each
/// immediate subfolder in name order, one group per folder.
fn collect(dir: &Path) -> Result<Vec<Entry>, CliError> {
    if !dir.is_dir() {
        return Err(CliError::BadInput(format!(
            "scenario folder {} does not exist (give one with --fixtures DIR)",
            dir.display()
        )));
    }
    let mut entries = load_group(dir, &group_name(dir))?;
    let mut subdirs: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|error| CliError::BadInput(format!("cannot read {}: {error}", dir.display())))?
        .filter_map(Result::ok)
        .map(|entry| entry.path())
        .filter(|path| path.is_dir())
        .collect();
    subdirs.sort();
    for subdir in subdirs {
        entries.extend(load_group(&subdir, &group_name(&subdir))?);
    }
    Ok(entries)
}

/// Runs the demo.
///
/// # Errors
/// [`CliError::BadInput`] when the scenario folder is missing or holds an
/// invalid file, or `--only` matches nothing; [`CliError::Output`] when the
/// page cannot be written.
pub(crate) fn run(options: &DemoOptions) -> Result<ExitStatus, CliError> {
    let (fixtures, mut entries) = match &options.fixtures {
        Some(dir) => (dir.display().to_string(), collect(dir)?),
        None => (
            "the bundled fixtures (paper, imazu, geo, coastal)".to_owned(),
            collect_bundled()?,
        ),
    };
    if !options.only.is_empty() {
        let known: Vec<String> = entries.iter().map(|entry| entry.stem.clone()).collect();
        entries.retain(|entry| {
            options
                .only
                .iter()
                .any(|only| *only == entry.scenario.name || *only == entry.stem)
        });
        if entries.is_empty() {
            return Err(CliError::BadInput(format!(
                "--only {} matches no scenario in {}; there are: {}",
                options.only.join(", "),
                fixtures,
                known.join(", ")
            )));
        }
    }
    if entries.is_empty() {
        return Err(CliError::BadInput(format!(
            "no scenario files (*.ron) in {fixtures} or its subfolders"
        )));
    }
    std::fs::create_dir_all(&options.out).map_err(|error| {
        CliError::Output(format!("cannot create {}: {error}", options.out.display()))
    })?;
    console::line(&format!(
        "running {} scenarios from {} into {}",
        entries.len(),
        fixtures,
        options.out.display()
    ));
    let started = Instant::now();
    let printer = OrderedLines::new(console::line);
    let outcomes: Vec<Outcome> = entries
        .into_par_iter()
        .enumerate()
        .map(|(index, entry)| {
            let clock = Instant::now();
            let seed = seed_for(&entry.scenario, options.seed);
            let result = run_scenario(&entry.scenario, seed).and_then(|run| {
                write_outputs(&entry.scenario, &run, &options.out.join(entry.folder()))?;
                Ok(run)
            });
            let passed = matches!(&result, Ok(run) if run.status() == ExitStatus::Success);
            let outcome = Outcome {
                entry,
                result: result.map(|run| run.report),
                passed,
                wall_time_s: clock.elapsed().as_secs_f64(),
            };
            printer.print(index, progress_line(&outcome));
            outcome
        })
        .collect();
    let page = index_html(&outcomes, &fixtures);
    let index = options.out.join("index.html");
    std::fs::write(&index, page)
        .map_err(|error| CliError::Output(format!("cannot write {}: {error}", index.display())))?;
    let safe = outcomes
        .iter()
        .filter(|outcome| matches!(&outcome.result, Ok(report) if report.reached_goal_safely))
        .count();
    let compliant = outcomes
        .iter()
        .filter(|outcome| matches!(&outcome.result, Ok(report) if report.compliant))
        .count();
    let failed = outcomes
        .iter()
        .filter(|outcome| outcome.result.is_err())
        .count();
    console::line(&format!(
        "{safe} of {} runs reached their goal safely, {compliant} obeyed COLREGs ({:.1} s); open {}",
        outcomes.len(),
        started.elapsed().as_secs_f64(),
        index.display()
    ));
    Ok(if failed > 0 {
        ExitStatus::BadInput
    } else if outcomes.iter().all(|outcome| outcome.passed) {
        ExitStatus::Success
    } else {
        ExitStatus::Unsafe
    })
}

/// Prints lines on stdout in the order of their indices (the scenarios'
/// order), each as soon as every line before it is out: runs finish in any
/// order on the worker threads, the console reads in the bundled order.
struct OrderedLines<Print: Fn(&str)> {
    /// The next index to print, and the lines that wait for it.
    pending: std::sync::Mutex<(usize, std::collections::BTreeMap<usize, String>)>,
    /// Where a line goes once its turn comes.
    print: Print,
}

impl<Print: Fn(&str)> OrderedLines<Print> {
    fn new(print: Print) -> Self {
        Self {
            pending: std::sync::Mutex::default(),
            print,
        }
    }

    fn print(&self, index: usize, line: String) {
        // A poisoned lock only means another run panicked; its lines are
        // still in order.
        let mut pending = self
            .pending
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let (next, waiting) = &mut *pending;
        waiting.insert(index, line);
        while let Some(line) = waiting.remove(next) {
            (self.print)(&line);
            *next += 1;
        }
    }
}

/// The width of the name column: the longest bundled scenario's folder
/// (`coastal/new_york_narrows_approach`), so the columns line up.
const NAME_WIDTH: usize = 34;

fn progress_line(outcome: &Outcome) -> String {
    let name = outcome.entry.folder().display().to_string();
    match &outcome.result {
        Ok(report) => format!(
            "  {name:<NAME_WIDTH$} {:<7} min {:>8} (d_th {:.0} m)  {:<9}  overhead path {:>5.1} %, time {:>5.1} %  {:.1} s",
            if report.reached_goal_safely {
                "safe"
            } else {
                "UNSAFE"
            },
            report
                .min_distance_m
                .map_or_else(|| "-".to_owned(), |d| format!("{d:.0} m")),
            report.d_th_m,
            if report.compliant {
                "compliant"
            } else {
                "violation"
            },
            report.path_overhead_pct,
            report.time_overhead_pct,
            outcome.wall_time_s
        ),
        Err(error) => format!("  {name:<NAME_WIDTH$} ERROR {error}"),
    }
}

/// Escapes text for HTML: the replay page's escaping, one place.
#[must_use]
pub(crate) fn escape(text: &str) -> String {
    crate::replay::escape_html(text)
}

/// A relative link path with forward slashes.
fn href(path: &Path) -> String {
    path.components()
        .map(|component| component.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}

fn verdict(ok: bool, yes: &str, no: &str) -> String {
    let class = if ok { "good" } else { "bad" };
    format!(
        "<td class=\"{class}\">{}</td>",
        escape(if ok { yes } else { no })
    )
}

const STYLE: &str = "
body { font-family: sans-serif; margin: 1.5em auto; max-width: 1250px; color: #222; padding: 0 1em; }
h1 { margin-bottom: 0.2em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.55em; text-align: left; }
th { background: #f0f0f0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.good { background: #e3f4e1; }
td.bad { background: #fbe0de; font-weight: bold; }
section { border-top: 2px solid #ddd; margin-top: 2em; padding-top: 0.5em; }
.plots { display: flex; flex-wrap: wrap; gap: 12px; }
.plots figure { margin: 0; }
.plots img { width: 600px; max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.85em; color: #555; }
.muted { color: #666; font-size: 0.9em; }
ul.violations { margin: 0; padding-left: 1.2em; }
";

fn index_html(outcomes: &[Outcome], fixtures: &str) -> String {
    let mut html = String::new();
    let safe = outcomes
        .iter()
        .filter(|o| matches!(&o.result, Ok(r) if r.reached_goal_safely))
        .count();
    let compliant = outcomes
        .iter()
        .filter(|o| matches!(&o.result, Ok(r) if r.compliant))
        .count();
    let _ = write!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>vorrt demo</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <h1>vorrt demo: {} scenarios</h1>\n\
         <p class=\"muted\">VORRT-COLREGs closed-loop runs of the scenarios in <code>{}</code>. \
         {safe} of {} reached their goal safely (no collision, clearance d_th kept); \
         {compliant} obeyed COLREGs in every encounter. Distances in metres; \
         plots in nautical miles. Each scenario's <code>report.json</code> is described in \
         <code>docs/report-format.md</code>.</p>\n",
        outcomes.len(),
        escape(fixtures),
        outcomes.len()
    );
    html.push_str(
        "<h2>Summary</h2>\n<table>\n<tr><th>scenario</th><th>group</th><th>targets</th>\
         <th>reached goal</th><th>collision</th><th>min distance (m)</th><th>d_th (m)</th>\
         <th>clearance</th><th>COLREGs</th><th>path overhead</th><th>time overhead</th>\
         <th>plans / replans / failed</th>\
         <th>planning (s)</th><th>report</th><th>replay</th></tr>\n",
    );
    for outcome in outcomes {
        let entry = &outcome.entry;
        let link = format!(
            "<a href=\"#{}\">{}</a>",
            escape(&entry.anchor()),
            escape(&entry.scenario.name)
        );
        match &outcome.result {
            Ok(report) => {
                let _ = writeln!(
                    html,
                    "<tr><td>{link}</td><td>{}</td><td class=\"num\">{}</td>{}{}\
                     <td class=\"num\">{}</td><td class=\"num\">{:.0}</td>{}{}\
                     <td class=\"num\">{:.1} %</td><td class=\"num\">{:.1} %</td>\
                     <td class=\"num\">{} / {} / {}</td>\
                     <td class=\"num\">{:.3}</td><td><a href=\"{}\">json</a></td>\
                     <td><a href=\"{}\">replay</a></td></tr>",
                    escape(&entry.group),
                    report.targets.len(),
                    verdict(report.reached_goal, "yes", "no"),
                    verdict(!report.collision, "no", "YES"),
                    report
                        .min_distance_m
                        .map_or_else(|| "-".to_owned(), |d| format!("{d:.1}")),
                    report.d_th_m,
                    verdict(report.clearance_kept, "kept", "broken"),
                    verdict(report.compliant, "compliant", "violated"),
                    report.path_overhead_pct,
                    report.time_overhead_pct,
                    report.planning.plans_made,
                    report.planning.replans,
                    report.planning.failed_plans,
                    report.planning.total_planning_time_s,
                    escape(&href(&entry.folder().join("report.json"))),
                    escape(&href(&entry.folder().join(crate::replay::REPLAY_HTML)))
                );
            }
            Err(error) => {
                let _ = writeln!(
                    html,
                    "<tr><td>{link}</td><td>{}</td><td class=\"bad\" colspan=\"13\">error: {}</td></tr>",
                    escape(&entry.group),
                    escape(&error.to_string())
                );
            }
        }
    }
    html.push_str("</table>\n");
    for outcome in outcomes {
        scenario_section(&mut html, outcome);
    }
    html.push_str("</body>\n</html>\n");
    html
}

fn scenario_section(html: &mut String, outcome: &Outcome) {
    let entry = &outcome.entry;
    let _ = writeln!(
        html,
        "<section id=\"{}\">\n<h2>{} <span class=\"muted\">({})</span></h2>",
        escape(&entry.anchor()),
        escape(&entry.scenario.name),
        escape(&href(&entry.folder()))
    );
    if let Some(description) = &entry.scenario.description {
        let _ = writeln!(html, "<p>{}</p>", escape(description));
    }
    let report = match &outcome.result {
        Ok(report) => report,
        Err(error) => {
            let _ = writeln!(
                html,
                "<p class=\"bad\">error: {}</p>\n</section>",
                escape(&error.to_string())
            );
            return;
        }
    };
    let folder = entry.folder();
    html.push_str("<div class=\"plots\">\n");
    for (stem, caption) in [
        (
            "trajectories",
            "Tracks (nm): closest approaches dashed, d_th circles",
        ),
        (
            "distance",
            "Distance to each target over time, d_th dashed red",
        ),
        ("speed", "Speed of every vessel over time, ownship black"),
    ] {
        let png = escape(&href(&folder.join(format!("{stem}.png"))));
        let svg = escape(&href(&folder.join(format!("{stem}.svg"))));
        let _ = writeln!(
            html,
            "<figure><a href=\"{png}\"><img src=\"{png}\" alt=\"{} {stem}\"></a>\
             <figcaption>{caption} (<a href=\"{svg}\">SVG</a>)</figcaption></figure>",
            escape(&entry.scenario.name)
        );
    }
    html.push_str("</div>\n");
    let _ = writeln!(
        html,
        "<p><a href=\"{}\">Replay the encounter</a> (time slider, tracks, findings on a timeline).</p>",
        escape(&href(&folder.join(crate::replay::REPLAY_HTML)))
    );
    let _ = writeln!(
        html,
        "<p>Seed {}; reached goal: <b>{}</b>{}; path {:.0} m vs {:.0} m straight \
         (overhead {:.1} %), {:.1} min vs {:.1} min straight at the service speed \
         (overhead {:.1} %); {} plans, {} replans, {} failed, {:.2} s planning; \
         run took {:.1} s.</p>",
        report.seed,
        if report.reached_goal { "yes" } else { "no" },
        report
            .arrival_time_s
            .map_or_else(String::new, |t| format!(" at {:.1} min", t / 60.0)),
        report.path_length_m,
        report.straight_length_m,
        report.path_overhead_pct,
        report.duration_s / 60.0,
        report.straight_duration_s / 60.0,
        report.time_overhead_pct,
        report.planning.plans_made,
        report.planning.replans,
        report.planning.failed_plans,
        report.planning.total_planning_time_s,
        outcome.wall_time_s
    );
    target_table(html, report);
    html.push_str("</section>\n");
}

/// The per-target table of a scenario's section.
fn target_table(html: &mut String, report: &Report) {
    html.push_str(
        "<table>\n<tr><th>target</th><th>encounter</th><th>role</th>\
         <th>min distance (m)</th><th>at (min)</th><th>clearance</th><th>compliant</th>\
         <th>score</th><th>violations</th></tr>\n",
    );
    for target in &report.targets {
        let violations = if target.violations.is_empty() {
            String::new()
        } else {
            let items = target
                .violations
                .iter()
                .fold(String::new(), |mut items, v| {
                    let _ = write!(items, "<li>{}</li>", escape(v));
                    items
                });
            format!("<ul class=\"violations\">{items}</ul>")
        };
        let _ = writeln!(
            html,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{:.1}</td>\
             <td class=\"num\">{:.1}</td>{}{}<td class=\"num\">{:.2}</td><td>{violations}</td></tr>",
            escape(&target.name),
            escape(&target.encounter),
            escape(&target.role),
            target.min_distance_m,
            target.time_of_min_s / 60.0,
            verdict(target.clearance_kept, "kept", "broken"),
            verdict(target.compliant, "yes", "no"),
            target.score
        );
    }
    html.push_str("</table>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }

    #[test]
    fn lines_come_out_in_index_order_whatever_order_they_finish_in() {
        let printed = std::sync::Mutex::new(Vec::new());
        let lines = OrderedLines::new(|line: &str| printed.lock().unwrap().push(line.to_owned()));
        lines.print(2, "c".into());
        lines.print(1, "b".into());
        assert!(printed.lock().unwrap().is_empty(), "waits for the first");
        lines.print(0, "a".into());
        lines.print(3, "d".into());
        assert_eq!(*printed.lock().unwrap(), ["a", "b", "c", "d"]);
    }

    #[test]
    fn links_use_forward_slashes() {
        assert_eq!(
            href(&Path::new("paper").join("crossing").join("x.png")),
            "paper/crossing/x.png"
        );
    }

    /// Every bundled scenario's name fits the column, so the lines align.
    #[test]
    fn every_bundled_name_fits_the_name_column() {
        for fixture in vorrt_scenarios::fixtures::BUNDLED {
            let name = format!("{}/{}", fixture.group, fixture.stem());
            assert!(name.len() <= NAME_WIDTH, "{name}");
        }
    }
}
