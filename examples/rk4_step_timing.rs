//! Prints the wall time per RK4 step of the 8-DOF (7-DOF reduced) helical
//! pair with time-varying mesh stiffness, seed-A parameters at 10,000 rpm,
//! 64 steps per mesh period. Output: one line `ns_per_step <value>`, read by
//! benches/dynamics_compare.py.
//!
//! Usage: cargo run --release --example rk4_step_timing [steps]

use std::time::Instant;
use thermobear::dynamics::batch::{advance_batch, pack, HelicalBatch, LANES};
use thermobear::dynamics::integrate::rk4_advance;
use thermobear::dynamics::{HelicalPair, HelicalPairParams};

fn main() -> thermobear::Result<()> {
    let steps: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000_000);
    let pair = HelicalPair::new(HelicalPairParams::seed_a())?;
    let sys = pair.system(10_000.0, 64)?;
    let mut x = pair.static_state()?;
    // Warm-up.
    rk4_advance(&sys, &mut x, 0, 100_000);
    let c0 = thread_cpu_s();
    let t0 = Instant::now();
    rk4_advance(&sys, &mut x, 0, steps);
    let dt = t0.elapsed().as_secs_f64();
    let cpu = thread_cpu_s().zip(c0).map(|(a, b)| a - b);
    // Keep the result observable so the loop is not optimised away.
    let dte = sys.relative_deflection_m(0, &x);
    eprintln!("final dte_m {dte:.6e}");
    // Wall time is what a user sees; on a shared machine the thread's CPU
    // time (from /proc, 10 ms resolution) is the better per-core figure.
    if let Some(c) = cpu {
        eprintln!("wall_ns_per_step {:.3}", dt * 1e9 / steps as f64);
        println!("ns_per_step {:.3}", c * 1e9 / steps as f64);
    } else {
        println!("ns_per_step {:.3}", dt * 1e9 / steps as f64);
    }
    // Lock-step lanes: LANES speeds at once; time per lane-step.
    let speeds: [f64; LANES] = std::array::from_fn(|l| 8000.0 + 1000.0 * l as f64);
    let systems = speeds.map(|s| pair.system(s, 64));
    let systems: Vec<_> = systems.into_iter().collect::<thermobear::Result<_>>()?;
    let batch = HelicalBatch::<LANES>::new(std::array::from_fn(|l| &systems[l]))?;
    let x0 = pair.static_state()?;
    let mut xb = pack(&[x0; LANES]);
    let batch_steps = steps / LANES;
    let c0 = thread_cpu_s();
    let t0 = Instant::now();
    advance_batch(&batch, &mut xb, batch_steps);
    let dt = t0.elapsed().as_secs_f64();
    let cpu = thread_cpu_s().zip(c0).map(|(a, b)| a - b).unwrap_or(dt);
    eprintln!("final lane-0 x_p {:.6e}", xb[0][0]);
    let lane_steps = (batch_steps * LANES) as f64;
    println!("batch_ns_per_lane_step {:.3}", cpu * 1e9 / lane_steps);
    eprintln!("batch_wall_ns_per_lane_step {:.3}", dt * 1e9 / lane_steps);
    Ok(())
}

/// CPU time of the calling thread (user + system) from /proc (Linux only).
fn thread_cpu_s() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/stat").ok()?;
    // Fields after the parenthesised command name; utime, stime are 14, 15.
    let rest = &s[s.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}
