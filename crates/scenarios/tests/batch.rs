//! Batches: sharding is deterministic (shards 0/2 and 1/2 are the whole
//! batch, row for row), rows survive CSV, and merged shards summarise as the
//! unsharded batch does. Heavy runs behind `VORRT_HEAVY_TESTS=1`.

use vorrt_scenarios::batch::{
    BatchRow, BatchSummary, Shard, generate_items, merge_rows, read_csv, read_shards, run_batch,
    write_csv, write_outputs,
};
use vorrt_scenarios::generator::{GeneratorSpec, OpenSeaSpec, TargetBehaviour, TssSpec};

fn heavy() -> bool {
    std::env::var("VORRT_HEAVY_TESTS").is_ok_and(|value| value == "1")
}

/// The row without its wall-clock times, which differ from run to run.
fn deterministic(row: &BatchRow) -> BatchRow {
    BatchRow {
        planning_time_ms: 0.0,
        planning_time_per_plan_ms: 0.0,
        ..row.clone()
    }
}

fn same_rows(a: &[BatchRow], b: &[BatchRow]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        let (x, y) = (deterministic(x), deterministic(y));
        // NaN != NaN: compare through the CSV text.
        assert_eq!(format!("{x:?}"), format!("{y:?}"));
    }
}

/// A summary without the wall-clock percentiles.
fn deterministic_summary(summary: &BatchSummary) -> String {
    let mut summary = summary.clone();
    summary.planning_time_ms = vorrt_scenarios::batch::Percentiles::of([]);
    summary.planning_time_per_plan_ms = summary.planning_time_ms;
    summary.to_json()
}

fn check_sharding(spec: &GeneratorSpec, seed: u64, count: u64) {
    let whole = generate_items(spec, seed, count, Shard::ALL).unwrap();
    assert_eq!(whole.len() as u64, count);
    let halves: Vec<_> = (0..2)
        .map(|index| generate_items(spec, seed, count, Shard { index, count: 2 }).unwrap())
        .collect();
    assert_eq!(halves[0].len() + halves[1].len(), whole.len());
    for half in &halves {
        for item in half {
            assert_eq!(&whole[usize::try_from(item.index).unwrap()], item);
        }
    }
    let whole_rows = run_batch(&whole, &|_, _| {});
    let shard_rows: Vec<Vec<BatchRow>> = halves
        .iter()
        .map(|half| run_batch(half, &|_, _| {}))
        .collect();
    // Every shard row equals the unsharded row of the same index.
    let merged = merge_rows(shard_rows.clone()).unwrap();
    same_rows(&merged, &whole_rows);
    // Through CSV files and `merge`: the summary of the merged shards is the
    // summary of their rows, and equals the unsharded one but for wall-clock
    // times.
    let dir = std::env::temp_dir().join(format!(
        "vorrt-batch-test-{}-{seed}-{count}",
        std::process::id()
    ));
    let shard_dirs: Vec<_> = shard_rows
        .iter()
        .enumerate()
        .map(|(index, rows)| {
            let shard_dir = dir.join(format!("shard-{index}"));
            write_outputs(rows, &shard_dir).unwrap();
            shard_dir
        })
        .collect();
    let read_back = read_shards(&shard_dirs).unwrap();
    assert_eq!(
        BatchSummary::from_rows(&read_back),
        BatchSummary::from_rows(&merged)
    );
    assert_eq!(
        deterministic_summary(&BatchSummary::from_rows(&read_back)),
        deterministic_summary(&BatchSummary::from_rows(&whole_rows))
    );
    // The same shard twice is refused.
    assert!(read_shards(&[shard_dirs[0].clone(), shard_dirs[0].clone()]).is_err());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn shards_make_the_whole_batch_and_merge_to_its_summary() {
    check_sharding(&GeneratorSpec::OpenSea(OpenSeaSpec::with_targets(2)), 17, 6);
}

#[test]
fn csv_round_trip_keeps_every_value() {
    let spec = GeneratorSpec::OpenSea(
        OpenSeaSpec::with_targets(1).with_behaviour(TargetBehaviour::SuddenTurn),
    );
    let items = generate_items(&spec, 4, 3, Shard::ALL).unwrap();
    let rows = run_batch(&items, &|_, _| {});
    let path = std::env::temp_dir().join(format!("vorrt-rows-{}.csv", std::process::id()));
    write_csv(&rows, &path).unwrap();
    let back = read_csv(&path).unwrap();
    std::fs::remove_file(&path).ok();
    assert_eq!(back, rows);
    let summary = BatchSummary::from_rows(&rows);
    assert_eq!(summary.count, 3);
    assert_eq!(summary.rules.len(), 5);
    assert!((0.0..=1.0).contains(&summary.success_rate));
}

#[test]
#[expect(clippy::float_cmp, reason = "the test pins exact results")]
fn progress_is_reported_for_every_run() {
    let spec = GeneratorSpec::Tss(TssSpec::with_density(0.5));
    let items = generate_items(&spec, 2, 3, Shard::ALL).unwrap();
    let seen = std::sync::Mutex::new(Vec::new());
    let rows = run_batch(&items, &|done, row| {
        seen.lock().unwrap().push((done, row.index));
    });
    let mut seen = seen.into_inner().unwrap();
    seen.sort_unstable();
    assert_eq!(
        seen.iter().map(|(done, _)| *done).collect::<Vec<_>>(),
        [1, 2, 3]
    );
    assert_eq!(
        rows.iter().map(|row| row.index).collect::<Vec<_>>(),
        [0, 1, 2]
    );
    assert!(rows.iter().all(|row| row.clearance_m == 100.0));
}

#[test]
fn heavy_sharding_over_every_generator_and_behaviour() {
    if !heavy() {
        return;
    }
    for behaviour in ["constant", "colregs", "noisy", "sudden-turn"] {
        let behaviour = TargetBehaviour::from_name(behaviour).unwrap();
        check_sharding(
            &GeneratorSpec::OpenSea(OpenSeaSpec::with_targets(8).with_behaviour(behaviour)),
            5,
            20,
        );
        check_sharding(
            &GeneratorSpec::Tss(TssSpec::with_density(3.0).with_behaviour(behaviour)),
            5,
            10,
        );
    }
}
