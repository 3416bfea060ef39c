//! Seed B spindle on solver-based bearing rows: linear vs nonlinear
//! supports, spectrum orders, hybrid vs steel, coupled vs uncoupled.

use thermobear::bearing::RacewayOffsets;
use thermobear::rotor::spindle_bearings::OffsetTable;
use thermobear::rotor::spindle_vibration::{RowMaterial, SpindleVibration, SpindleVibrationConfig, UnbalanceSpec};
use thermobear::{Effect, EffectSet};

fn spindle(material: RowMaterial) -> SpindleVibration {
    SpindleVibration::new(SpindleVibrationConfig::seed(material)).unwrap()
}

#[test]
fn nonlinear_ball_forces_reproduce_the_linear_steady_response_at_small_amplitude() {
    // Start both time responses in the linear steady state at 12,000 rpm
    // and integrate 12 revolutions. With the linearised supports the
    // response must stay on the harmonic solution (Newmark period error
    // (2 pi / 64)^2 / 12 = 0.08 % per revolution of phase); with the full
    // ball forces the difference is the nonlinearity, of relative size
    // amplitude / preload approach (~0.1 um / ~10 um = 1 %), plus the
    // ball-pass stiffness ripple (isotropic to < 0.1 % for Z >= 3); the
    // quadratic part of the nonlinearity feeds 0X and 2X, not 1X, so the
    // 1X amplitudes of the two time responses must agree within 1 %
    // (measured: 1e-4), and the time response must match the frequency
    // domain within 1 % (Hann-windowed DFT at the exact 1X frequency over
    // 12 revolutions; measured < 1e-3).
    let s = spindle(RowMaterial::Hybrid);
    let u = s.unbalance(UnbalanceSpec::MassRadius { unbalance_g_mm: 50.0 }).unwrap();
    let speed = 12_000.0;
    let steady = s.steady_vibration(&[speed], &u).unwrap()[0];
    let lin = s.time_vibration(speed, 0.06, 0.0, &u, false).unwrap();
    let nl = s.time_vibration(speed, 0.06, 0.0, &u, true).unwrap();
    let x1 = steady.harmonics_mm_s[0];
    assert!(x1 > 0.0);
    let rel_lin = (lin.point.harmonics_mm_s[0] / x1 - 1.0).abs();
    let rel_nl = (nl.point.harmonics_mm_s[0] / lin.point.harmonics_mm_s[0] - 1.0).abs();
    assert!(rel_lin < 0.01, "linear time vs frequency domain: {rel_lin}");
    assert!(rel_nl < 0.01, "nonlinear vs linear: {rel_nl}");
    // The nonlinear run is not the linear one replayed.
    assert_ne!(lin.history.velocity_x_m_per_s, nl.history.velocity_x_m_per_s);
}

#[test]
fn spectrum_peaks_at_the_rotation_frequency() {
    // 1X of an unbalance is the shaft frequency speed / 60 (200 Hz at
    // 12,000 rpm), to within one FFT bin.
    let s = spindle(RowMaterial::Steel);
    let u = s.unbalance(UnbalanceSpec::Grade { grade_mm_per_s: 2.5 }).unwrap();
    let t = s.time_vibration(12_000.0, 0.1, 0.0, &u, false).unwrap();
    let (f, a) = s.spectrum(&t).unwrap();
    let k = (1..a.len()).max_by(|&i, &j| a[i].total_cmp(&a[j])).unwrap();
    let bin = f[1] - f[0];
    assert!((f[k] - 200.0).abs() <= bin, "{} Hz, bin {bin}", f[k]);
    // The 1X order amplitude (exact-frequency DFT) bounds the bin-picked peak
    // from above (Hann scalloping, Harris 1978: at most 1.42 dB).
    assert!(a[k] <= t.point.harmonics_mm_s[0] * 1.001 && a[k] >= 0.84 * t.point.harmonics_mm_s[0]);
}

#[test]
fn hybrid_rows_raise_the_first_natural_frequency() {
    // Si3N4 balls (E = 310 GPa vs 208 GPa) stiffen each Hertz contact, and
    // weigh 41 % of steel, so they lose less contact load to centrifugal
    // force at speed: under the same 400 N preload the hybrid rows are
    // stiffer radially and the first bending mode of the spindle is higher,
    // at rest and at 18,000 rpm.
    let st = spindle(RowMaterial::Steel);
    let hy = spindle(RowMaterial::Hybrid);
    let speeds = [0.0, 18_000.0];
    let ds = st.campbell(&speeds, 2).unwrap();
    let dh = hy.campbell(&speeds, 2).unwrap();
    for (i, n) in speeds.iter().enumerate() {
        let (fs, fh) = (ds.points[i].modes[0].frequency_hz, dh.points[i].modes[0].frequency_hz);
        assert!(fh > fs * 1.01, "{n} rpm: hybrid {fh} vs steel {fs}");
    }
}

#[test]
fn zero_offsets_are_the_uncoupled_model_exactly_and_ump_is_switchable() {
    let zero = OffsetTable::new(vec![0.0, 30_000.0], vec![RacewayOffsets::default(); 2]).unwrap();
    let mut c = SpindleVibrationConfig::seed(RowMaterial::Hybrid);
    c.front_offsets = Some(zero.clone());
    c.rear_offsets = Some(zero);
    let coupled = SpindleVibration::new(c).unwrap();
    let plain = spindle(RowMaterial::Hybrid);
    let u = plain.unbalance(UnbalanceSpec::Grade { grade_mm_per_s: 2.5 }).unwrap();
    let speeds = [6_000.0, 18_000.0];
    assert_eq!(
        coupled.steady_vibration(&speeds, &u).unwrap(),
        plain.steady_vibration(&speeds, &u).unwrap()
    );
    // UMP: a negative stiffness at the core lowers the first natural frequency.
    let mut c = SpindleVibrationConfig::seed(RowMaterial::Hybrid);
    c.effects = EffectSet::all().with(Effect::UnbalancedMagneticPull);
    let ump = SpindleVibration::new(c).unwrap();
    let f_plain = plain.campbell(&[0.0], 1).unwrap().points[0].modes[0].frequency_hz;
    let f_ump = ump.campbell(&[0.0], 1).unwrap().points[0].modes[0].frequency_hz;
    assert!(f_ump < f_plain, "{f_ump} vs {f_plain}");
}
