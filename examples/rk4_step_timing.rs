//! Prints the cost per RK4 step of the 8-DOF (7-DOF reduced) helical pair
//! with time-varying mesh stiffness, seed-A parameters around 10,000 rpm,
//! 64 steps per mesh period: one trajectory (the kernel and the reference
//! four-evaluation RK4), then lock-step lanes on every instruction set this
//! CPU has (2, 4 and 8 lanes).
//!
//! Times are the thread's CPU time (from /proc/thread-self/schedstat, ns
//! resolution, Linux), which on a shared machine is steadier than wall time;
//! wall time is printed to stderr. stdout lines `ns_per_step <value>` and
//! `batch_ns_per_lane_step <value>` (detected instruction set, 8 lanes) are
//! read by benches/dynamics_compare.py.
//!
//! Usage: cargo run --release --example rk4_step_timing [steps]

use std::time::Instant;
use thermobear::dynamics::batch::{advance_batch_with, pack, HelicalBatch, Isa, LANES};
use thermobear::dynamics::integrate::{rk4_advance, rk4_step_generic};
use thermobear::dynamics::{HelicalPair, HelicalPairParams, HelicalPairSystem};

/// CPU and wall seconds of `f`. The kernel updates a running thread's CPU
/// time at scheduler ticks (a few ms), so runs under 0.25 s report their
/// wall time as CPU time.
fn timed(f: impl FnOnce()) -> (f64, f64) {
    let c0 = thread_cpu_s();
    let t0 = Instant::now();
    f();
    let wall = t0.elapsed().as_secs_f64();
    let cpu = thread_cpu_s().zip(c0).map_or(wall, |(a, b)| a - b);
    (if wall < 0.25 { wall } else { cpu }, wall)
}

fn lanes<const L: usize>(isa: Isa, pair: &HelicalPair, steps: usize) -> thermobear::Result<(f64, f64)> {
    let systems = (0..L)
        .map(|l| pair.system(8000.0 + 1000.0 * l as f64, 64))
        .collect::<thermobear::Result<Vec<HelicalPairSystem>>>()?;
    let batch = HelicalBatch::<L>::new(std::array::from_fn(|l| &systems[l]))?;
    let mut x = pack(&[pair.static_state()?; L]);
    advance_batch_with(isa, &batch, &mut x, 10_000)?;
    let batch_steps = steps / L;
    let mut res = Ok(());
    let (cpu, wall) = timed(|| res = advance_batch_with(isa, &batch, &mut x, batch_steps));
    res?;
    eprintln!("  final lane-0 x_p {:.6e}", x[0][0]);
    let lane_steps = (batch_steps * L) as f64;
    Ok((cpu * 1e9 / lane_steps, wall * 1e9 / lane_steps))
}

fn main() -> thermobear::Result<()> {
    let steps: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000_000);
    let pair = HelicalPair::new(HelicalPairParams::seed_a())?;
    let sys = pair.system(10_000.0, 64)?;
    let x0 = pair.static_state()?;

    let mut x = x0;
    rk4_advance(&sys, &mut x, 0, 100_000);
    let (cpu, wall) = timed(|| {
        rk4_advance(&sys, &mut x, 0, steps);
    });
    eprintln!("final dte_m {:.6e}", sys.relative_deflection_m(0, &x));
    eprintln!("wall_ns_per_step {:.3}", wall * 1e9 / steps as f64);
    println!("ns_per_step {:.3}", cpu * 1e9 / steps as f64);

    // The reference RK4 (four right-hand-side evaluations), for comparison.
    let ref_steps = steps / 4;
    let mut y = x0;
    let (cpu, _) = timed(|| {
        for n in 0..ref_steps {
            rk4_step_generic(&sys, n % 64, &mut y);
        }
    });
    eprintln!("final reference dte_m {:.6e}", sys.relative_deflection_m(0, &y));
    println!("reference_ns_per_step {:.3}", cpu * 1e9 / ref_steps as f64);

    // Lock-step lanes (speeds 8000, 9000, ... rpm) per instruction set.
    let mut best = f64::NAN;
    for isa in Isa::available() {
        let l2 = lanes::<2>(isa, &pair, steps)?;
        let l4 = lanes::<4>(isa, &pair, steps)?;
        let l8 = lanes::<8>(isa, &pair, steps)?;
        println!(
            "{:<8} ns_per_lane_step: 2 lanes {:.3}, 4 lanes {:.3}, 8 lanes {:.3} (wall {:.3} / {:.3} / {:.3})",
            isa.name(),
            l2.0,
            l4.0,
            l8.0,
            l2.1,
            l4.1,
            l8.1
        );
        if isa == Isa::detected() {
            best = l8.0;
        }
    }
    debug_assert_eq!(LANES, 8);
    println!("batch_ns_per_lane_step {best:.3}");
    Ok(())
}

/// CPU time of the calling thread from /proc/thread-self/schedstat (first
/// field: nanoseconds on the CPU; Linux only).
fn thread_cpu_s() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = s.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}
