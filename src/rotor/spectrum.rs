//! Vibration metrics and spectra of sampled signals: RMS, peak, an
//! iterative radix-2 FFT (Cooley & Tukey 1965), the Hann window and
//! amplitude-correct harmonic amplitudes (1X, 2X, 3X).
//!
//! Amplitude correction: for a windowed sinusoid of amplitude A the DFT at
//! its frequency is A sum(w) / 2, so A = 2 |X(f)| / sum(w) (Harris, Proc.
//! IEEE 66 (1978) 51-83, "coherent gain").

use std::f64::consts::PI;

use nalgebra::Complex;

use crate::error::{positive, Error, Result};

/// Root mean square of a signal.
pub fn rms(signal: &[f64]) -> f64 {
    if signal.is_empty() {
        return 0.0;
    }
    (signal.iter().map(|x| x * x).sum::<f64>() / signal.len() as f64).sqrt()
}

/// Largest absolute value of a signal.
pub fn peak(signal: &[f64]) -> f64 {
    signal.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Periodic Hann window w_n = 0.5 (1 - cos(2 pi n / N)).
pub fn hann(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| 0.5 * (1.0 - (2.0 * PI * i as f64 / n as f64).cos()))
        .collect()
}

/// In-place iterative radix-2 FFT, X_k = sum x_n e^{-2 pi i k n / N}.
/// The length must be a power of two.
pub fn fft_in_place(data: &mut [Complex<f64>]) -> Result<()> {
    let n = data.len();
    if n == 0 || !n.is_power_of_two() {
        return Err(Error::config("fft_length", n, "must be a power of two"));
    }
    // Bit-reversal permutation.
    let bits = n.trailing_zeros();
    for i in 0..n {
        let j = if bits == 0 {
            0
        } else {
            i.reverse_bits() >> (usize::BITS - bits)
        };
        if j > i {
            data.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let step = Complex::from_polar(1.0, -2.0 * PI / len as f64);
        for start in (0..n).step_by(len) {
            let mut w = Complex::new(1.0, 0.0);
            for k in 0..len / 2 {
                let a = data[start + k];
                let b = data[start + k + len / 2] * w;
                data[start + k] = a + b;
                data[start + k + len / 2] = a - b;
                w *= step;
            }
        }
        len *= 2;
    }
    Ok(())
}

/// One-sided amplitude spectrum of a real signal with a Hann window,
/// zero-padded to the next power of two. Returns (frequencies \[Hz\],
/// amplitudes [signal units, peak]).
pub fn amplitude_spectrum(signal: &[f64], sample_rate_hz: f64) -> Result<(Vec<f64>, Vec<f64>)> {
    positive("sample_rate_hz", sample_rate_hz)?;
    if signal.len() < 2 {
        return Err(Error::config(
            "signal_length",
            signal.len(),
            "need at least two samples",
        ));
    }
    let w = hann(signal.len());
    let gain: f64 = w.iter().sum();
    let n = signal.len().next_power_of_two();
    let mut data = vec![Complex::new(0.0, 0.0); n];
    for (i, (x, wi)) in signal.iter().zip(&w).enumerate() {
        data[i] = Complex::new(x * wi, 0.0);
    }
    fft_in_place(&mut data)?;
    let freqs = (0..=n / 2).map(|k| k as f64 * sample_rate_hz / n as f64).collect();
    let amps = (0..=n / 2)
        .map(|k| {
            let one_sided = if k == 0 || k == n / 2 { 1.0 } else { 2.0 };
            one_sided * data[k].norm() / gain
        })
        .collect();
    Ok((freqs, amps))
}

/// Amplitude of the component at `frequency_hz` (Hann window, direct DFT
/// at that exact frequency, amplitude-corrected).
pub fn harmonic_amplitude(signal: &[f64], sample_rate_hz: f64, frequency_hz: f64) -> Result<f64> {
    positive("sample_rate_hz", sample_rate_hz)?;
    positive("frequency_hz", frequency_hz)?;
    if frequency_hz >= 0.5 * sample_rate_hz {
        return Err(Error::config(
            "frequency_hz",
            frequency_hz,
            format!("must lie below the Nyquist frequency {} Hz", 0.5 * sample_rate_hz),
        ));
    }
    if signal.len() < 2 {
        return Err(Error::config(
            "signal_length",
            signal.len(),
            "need at least two samples",
        ));
    }
    let w = hann(signal.len());
    let gain: f64 = w.iter().sum();
    let dphi = -2.0 * PI * frequency_hz / sample_rate_hz;
    let mut acc = Complex::new(0.0, 0.0);
    for (i, (x, wi)) in signal.iter().zip(&w).enumerate() {
        acc += Complex::from_polar(x * wi, dphi * i as f64);
    }
    Ok(2.0 * acc.norm() / gain)
}

/// Amplitudes of the first `orders` rotation harmonics (1X, 2X, ...).
pub fn order_amplitudes(signal: &[f64], sample_rate_hz: f64, speed_rpm: f64, orders: usize) -> Result<Vec<f64>> {
    positive("speed_rpm", speed_rpm)?;
    (1..=orders)
        .map(|k| harmonic_amplitude(signal, sample_rate_hz, k as f64 * speed_rpm / 60.0))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fft_matches_direct_dft() {
        let n = 64;
        let x: Vec<Complex<f64>> = (0..n)
            .map(|i| Complex::new((0.3 * i as f64).sin() + 0.1 * i as f64, (0.7 * i as f64).cos()))
            .collect();
        let mut y = x.clone();
        fft_in_place(&mut y).unwrap();
        for k in [0, 1, 7, 31, 63] {
            let d: Complex<f64> = x
                .iter()
                .enumerate()
                .map(|(j, v)| v * Complex::from_polar(1.0, -2.0 * PI * (k * j) as f64 / n as f64))
                .sum();
            assert!((d - y[k]).norm() < 1e-9 * d.norm().max(1.0));
        }
        assert!(fft_in_place(&mut [Complex::new(0.0, 0.0); 3]).is_err());
    }

    #[test]
    fn hann_amplitudes_of_known_harmonics() {
        // 1X at 196.6 Hz (the 1X line of seed B's spectrum at 12,000 rpm) with
        // 1X, 2X, 3X amplitudes 3, 1, 0.5 off-bin; RMS of a sum of sines = sqrt(sum A^2 / 2).
        let fs = 10_000.0;
        let f1 = 196.6;
        let sig: Vec<f64> = (0..8000)
            .map(|i| {
                let t = i as f64 / fs;
                3.0 * (2.0 * PI * f1 * t).sin()
                    + 1.0 * (4.0 * PI * f1 * t + 0.3).cos()
                    + 0.5 * (6.0 * PI * f1 * t).sin()
            })
            .collect();
        let a = order_amplitudes(&sig, fs, f1 * 60.0, 3).unwrap();
        for (got, want) in a.iter().zip([3.0, 1.0, 0.5]) {
            assert!((got - want).abs() < 2e-3 * want.max(1.0), "{got} vs {want}");
        }
        let (f, amp) = amplitude_spectrum(&sig, fs).unwrap();
        let k = amp
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.total_cmp(y.1))
            .map(|(i, _)| i)
            .unwrap();
        assert!((f[k] - f1).abs() <= fs / 8192.0);
        // Bin-picked peak with Hann scalloping loss <= 1.42 dB (Harris 1978).
        assert!(amp[k] > 3.0 * 0.849 && amp[k] <= 3.0 * 1.001);
        assert!((rms(&sig) - (0.5 * (9.0 + 1.0 + 0.25_f64)).sqrt()).abs() < 1e-2);
        assert!((peak(&[1.0, -4.0, 2.0]) - 4.0).abs() < 1e-15);
        assert!(harmonic_amplitude(&sig, fs, 6_000.0).is_err());
    }
}
