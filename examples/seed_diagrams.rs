//! The seed's bifurcation diagram set (A, Figs. 14-15): 1001 speeds from
//! 6,500 to 16,500 rpm x 3 bearing-stiffness cases x up/down continuation
//! (6 sweeps), 300 transient + 100 recorded mesh periods, 64 RK4 steps per
//! mesh period, on a 2-thread rayon pool; then a small torque x speed
//! regime map.
//!
//! Mesh and bearing stiffness are computed (src/dynamics/seed.rs): the
//! constant and speed-dependent 6208 cases, and the thermal case from the
//! coupled thermal model at the seed operating point
//! (`CoupledBearing::seed_a`, level inner ring). The bearing solves are not
//! timed; the sweep set's wall and CPU time are printed.
//!
//! Usage: cargo run --release --example seed_diagrams [speeds] [threads]

use std::time::Instant;
use thermobear::bearing::{SolveOptions, Tilt};
use thermobear::dynamics::batch::Isa;
use thermobear::dynamics::*;
use thermobear::thermal::coupled::{stiffness_curve_mode, CoupledBearing, CoupledOptions, StiffnessMode};

/// Bearing stiffness at the coupled thermal steady state of each speed,
/// `per_shaft` bearings in parallel (the Python "thermal" case).
fn thermal_schedule(
    bearing: &thermobear::Bearing,
    grid: &[f64],
    fa: f64,
    fr: f64,
    per_shaft: usize,
) -> thermobear::Result<BearingSchedule> {
    let d = CoupledOptions::default();
    let options = CoupledOptions {
        solve: SolveOptions {
            tilt: Tilt::held_level(),
            ..d.solve
        },
        ..d
    };
    let coupled = CoupledBearing::seed_a(bearing, options)?;
    let states = stiffness_curve_mode(&coupled, grid, fa, fr, StiffnessMode::Thermal)?;
    let n = per_shaft as f64;
    BearingSchedule::new(
        grid.iter()
            .zip(&states)
            .map(|(&s, (b, _))| {
                (
                    s,
                    n * b.radial_stiffness_seed_n_per_m,
                    n * b.axial_stiffness_seed_n_per_m,
                )
            })
            .collect(),
    )
}

fn summary(r: &SweepResult) -> String {
    let mut per1 = 0;
    let mut pern = 0;
    let mut qp = 0;
    let mut ch = 0;
    let mut imp = 0;
    for p in &r.points {
        match p.motion {
            Motion::Periodic(1) => per1 += 1,
            Motion::Periodic(_) => pern += 1,
            Motion::QuasiPeriodic => qp += 1,
            Motion::Chaotic => ch += 1,
        }
        if p.impact != ImpactRegime::NoImpact {
            imp += 1;
        }
    }
    let to_chaos = r.transitions.iter().filter(|t| t.enters_chaos()).count();
    let from_chaos = r.transitions.iter().filter(|t| t.exits_chaos()).count();
    format!(
        "{:?}: P1 {per1}, Pn {pern}, QP {qp}, chaos {ch}, impacting {imp}, jumps {:?}, \
         chaos entries {to_chaos} / exits {from_chaos}, unsettled {}",
        r.direction,
        r.jumps,
        r.unsettled.len()
    )
}

fn print_map(cells: &[RegimeCell], row_len: usize) {
    for chunk in cells.chunks(row_len) {
        let row: String = chunk
            .iter()
            .map(|c| {
                let ch = match c.motion {
                    Motion::Periodic(1) if c.impact == ImpactRegime::NoImpact => '1',
                    Motion::Periodic(1) => '*',
                    Motion::Periodic(k) if k < 10 => char::from_digit(k as u32, 10).unwrap_or('n'),
                    Motion::Periodic(_) => 'n',
                    Motion::QuasiPeriodic => 'q',
                    Motion::Chaotic => 'c',
                };
                if c.impact == ImpactRegime::DoubleSided {
                    ch.to_ascii_uppercase()
                } else {
                    ch
                }
            })
            .collect();
        println!(
            "  T = {:>5.1} N m, TE x{}: {row}",
            chunk[0].input_torque_n_m, chunk[0].error_scale
        );
    }
}

fn main() -> thermobear::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1001);
    let threads: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(2);
    // Computed wiring (src/dynamics/seed.rs): potential-energy mesh stiffness
    // in the normal direction, two 6208 per shaft in parallel under the seed
    // loads; the thermal case comes from the thermal module (Python side).
    let defaults = GearSystemDefaults::default();
    let pair = HelicalPair::new(seed_a_params(&defaults)?)?;
    let bearing = thermobear::Bearing::preset("6208")?;
    let (fa, fr) = seed_bearing_loads(100.0)?;
    let grid: Vec<f64> = (0..=44).map(|i| 6000.0 + 250.0 * i as f64).collect();
    let t0 = Instant::now();
    let cases = [
        (
            "constant",
            bearing_schedule(&bearing, BearingCase::Constant, &grid, fa, fr, 2)?,
        ),
        (
            "speed, no thermal",
            bearing_schedule(&bearing, BearingCase::Speed, &grid, fa, fr, 2)?,
        ),
        ("thermal", thermal_schedule(&bearing, &grid, fa, fr, 2)?),
    ];
    println!(
        "bearing stiffness of 3 cases at {} speeds: {:.2} s (not part of the set's time)",
        grid.len(),
        t0.elapsed().as_secs_f64()
    );
    let models: Vec<HelicalSweep> = cases
        .iter()
        .map(|(_, b)| HelicalSweep {
            pair: pair.clone(),
            bearings: b.clone(),
        })
        .collect();
    let mut jobs = Vec::new();
    for m in &models {
        jobs.push((m, SweepDirection::Up));
        jobs.push((m, SweepDirection::Down));
    }
    let speeds: Vec<f64> = (0..n)
        .map(|i| 6500.0 + 10_000.0 * i as f64 / (n - 1).max(1) as f64)
        .collect();
    let cfg = SweepConfig::default();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| thermobear::Error::config("threads", threads, e.to_string()))?;
    let c0 = process_cpu_s();
    let t0 = Instant::now();
    let res = pool.install(|| sweep_many(&jobs, &speeds, &cfg, &|_, _| true))?;
    let dt = t0.elapsed().as_secs_f64();
    let cpu = process_cpu_s().zip(c0).map(|(a, b)| a - b);
    let lane_steps = (jobs.len() * n * (cfg.transient_periods + cfg.recorded_periods) * cfg.steps_per_period) as f64;
    println!(
        "seed set: {} speeds x {} sweeps on {threads} threads ({}): {dt:.2} s wall, {} s CPU ({:.1} CPU-ns per lane-step)",
        n,
        jobs.len(),
        Isa::detected().name(),
        cpu.map_or("?".into(), |c| format!("{c:.2}")),
        cpu.unwrap_or(f64::NAN) * 1e9 / lane_steps
    );
    for (k, r) in res.iter().enumerate() {
        println!("  {:<18} {}", cases[k / 2].0, summary(r));
    }

    // Regime map over torque x speed (TE x1 and x5), independent starts,
    // for both mesh-damping options.
    let torques = [5.0, 10.0, 20.0, 50.0, 100.0];
    let map_speeds: Vec<f64> = (0..21).map(|i| 6500.0 + 500.0 * i as f64).collect();
    for damping in [MeshDamping::InContact, MeshDamping::Always] {
        let mut p = seed_a_params(&defaults)?;
        p.mesh_damping = damping;
        let base = HelicalSweep {
            pair: HelicalPair::new(p)?,
            bearings: cases[0].1.clone(),
        };
        let t0 = Instant::now();
        let cells = pool.install(|| regime_map(&base, &torques, &[1.0, 5.0], &map_speeds, &cfg, &|_, _| true))?;
        println!(
            "regime map, mesh damping {damping:?} ({} cells, 6500..16500 rpm step 500): {:.2} s",
            cells.len(),
            t0.elapsed().as_secs_f64()
        );
        println!("  1 = P1 no impact, * = P1 impacting, 2-9 = period-n, n = period 10-32, q = quasi-periodic, c = chaos; upper case = double-sided");
        print_map(&cells, map_speeds.len());
    }
    Ok(())
}

/// CPU time (user + system) of this process from /proc (Linux only); on a
/// shared machine wall time includes waiting for other processes.
fn process_cpu_s() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/stat").ok()?;
    let rest = &s[s.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    Some((f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?) / 100.0)
}
