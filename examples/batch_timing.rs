//! Native time per operating point of the bearing solve, for comparison with
//! `Bearing.solve_many` from Python (benches/study_overhead.py runs the same
//! points: 7008C, 500 N axial, radial 0..500 N, 1000..20,000 rpm, ring held
//! level, all effects).
//!
//! cargo run --release --example batch_timing [points] [single]
//!
//! With `single` only the one-thread loop of bare solves runs (the caller
//! can then read the process's CPU time: on a loaded machine wall time
//! says little).

use std::time::Instant;

use thermobear::bearing::batch::{solve_many, OperatingPoint};
use thermobear::bearing::state::Tilt;
use thermobear::bearing::{BearingModel, SolveOptions};
use thermobear::Bearing;

fn main() -> thermobear::Result<()> {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20_000);
    let b = Bearing::preset("7008C")?;
    let model = BearingModel::new(&b)?;
    let opts = SolveOptions {
        tilt: Tilt::held_level(),
        ..Default::default()
    };
    let at = |i: usize| i as f64 / (n - 1).max(1) as f64;
    let points: Vec<OperatingPoint> = (0..n)
        .map(|i| OperatingPoint {
            load: [500.0 * at(i), 0.0, 500.0, 0.0, 0.0],
            speed_rpm: 1000.0 + 19_000.0 * at(i),
            options: opts,
        })
        .collect();
    // One thread: the bare solve, point after point.
    let t = Instant::now();
    let mut ok = 0;
    for p in &points {
        ok += model.solve(&p.load, p.speed_rpm, &p.options).is_ok() as usize;
    }
    let single = t.elapsed().as_secs_f64() / n as f64;
    if std::env::args().nth(2).as_deref() == Some("single") {
        println!("points {n}, solved {ok}");
        println!("native solve, 1 thread:        {:8.2} us/point", single * 1e6);
        return Ok(());
    }
    // The batch in a one-thread pool and in the global pool.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("pool");
    let t = Instant::now();
    let one = pool.install(|| solve_many(&model, &points));
    let batch1 = t.elapsed().as_secs_f64() / n as f64;
    let t = Instant::now();
    let all = solve_many(&model, &points);
    let batch_all = t.elapsed().as_secs_f64() / n as f64;
    assert_eq!(one, all, "the batch depends on the thread count");
    println!("points {n}, solved {ok}");
    println!("native solve, 1 thread:        {:8.2} us/point", single * 1e6);
    println!("native solve_many, 1 thread:   {:8.2} us/point", batch1 * 1e6);
    println!(
        "native solve_many, {} threads:  {:8.2} us/point",
        rayon::current_num_threads(),
        batch_all * 1e6
    );
    Ok(())
}
