use thermobear::dynamics::*;
fn main() -> thermobear::Result<()> {
    let pair = HelicalPair::new(HelicalPairParams::seed_a())?;
    println!(
        "T_min {:e} s, cm {:e}",
        pair.shortest_natural_period_s(),
        pair.mesh_damping_n_s_per_m()
    );
    let (w, _) = pair.natural_modes(6e8);
    println!("f_n Hz {:?}", w.iter().map(|w| w / 6.283).collect::<Vec<_>>());
    println!(
        "mesh freq at 6500 {} 16500 {}",
        6500.0 * 29.0 / 60.0,
        16500.0 * 29.0 / 60.0
    );
    let model = HelicalSweep {
        pair: pair.clone(),
        bearings: BearingSchedule::constant(2e8, 5e7)?,
    };
    let speeds: Vec<f64> = (0..21).map(|i| 6500.0 + 500.0 * i as f64).collect();
    let cfg = SweepConfig::default();
    let r = sweep(&model, &speeds, SweepDirection::Up, &cfg, &|_, _| true)?;
    for p in &r.points {
        println!(
            "{} {:?} {:?} min {:.3e} max {:.3e} lyap {:?}",
            p.speed, p.motion, p.impact, p.deflection_min, p.deflection_max, p.lyapunov_per_period
        );
    }
    for (t, e) in [(10.0, 5.0), (20.0, 10.0)] {
        let m2 = HelicalSweep {
            pair: pair.with_torque_and_error_scale(t, e)?,
            bearings: BearingSchedule::constant(2e8, 5e7)?,
        };
        let r = sweep(&m2, &speeds, SweepDirection::Up, &cfg, &|_, _| true)?;
        println!("torque {t} te x{e}");
        for p in &r.points {
            println!(
                "{} {:?} {:?} min {:.3e} max {:.3e} lyap {:?}",
                p.speed, p.motion, p.impact, p.deflection_min, p.deflection_max, p.lyapunov_per_period
            );
        }
    }
    Ok(())
}
