//! Amplitude spectrum of a uniformly sampled signal: mean removed, Hann window, radix-2 FFT
//! (Cooley & Tukey 1965) on the largest power-of-two tail of the record, amplitudes scaled so a
//! sinusoid of amplitude A shows a peak of about A (window coherent gain ½ corrected).

use nalgebra::Complex;

/// In-place iterative radix-2 FFT; `x.len()` must be a power of two.
fn fft(x: &mut [Complex<f64>]) {
    let n = x.len();
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            x.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let angle = -2.0 * std::f64::consts::PI / len as f64;
        let w_len = Complex::new(angle.cos(), angle.sin());
        for start in (0..n).step_by(len) {
            let mut w = Complex::new(1.0, 0.0);
            for k in 0..len / 2 {
                let u = x[start + k];
                let v = x[start + k + len / 2] * w;
                x[start + k] = u + v;
                x[start + k + len / 2] = u - v;
                w *= w_len;
            }
        }
        len <<= 1;
    }
}

/// One-sided amplitude spectrum: (frequency (Hz), amplitude) pairs for a signal sampled every
/// `dt` seconds. Empty when fewer than 8 samples.
pub fn amplitude_spectrum(signal: &[f64], dt: f64) -> Vec<(f64, f64)> {
    let mut n = 1usize;
    while n * 2 <= signal.len() {
        n *= 2;
    }
    if n < 8 {
        return Vec::new();
    }
    let tail = &signal[signal.len() - n..];
    let mean = tail.iter().sum::<f64>() / n as f64;
    let mut x: Vec<Complex<f64>> = tail
        .iter()
        .enumerate()
        .map(|(i, &s)| {
            let hann = 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / n as f64).cos();
            Complex::new((s - mean) * hann, 0.0)
        })
        .collect();
    fft(&mut x);
    (0..n / 2)
        .map(|k| (k as f64 / (n as f64 * dt), 4.0 * x[k].norm() / n as f64))
        .collect()
}

#[cfg(test)]
mod tests {
    /// Reference: a pure sinusoid of amplitude 2 at a bin frequency gives a peak of 2 there.
    #[test]
    fn sinusoid_peak_has_its_amplitude_and_frequency() {
        let dt = 1e-3;
        let f0: f64 = 125.0; // 1024 samples → bin spacing 0.9765625 Hz, 128 bins
        let f0 = (f0 / (1.0 / (1024.0 * dt))).round() / (1024.0 * dt);
        let s: Vec<f64> = (0..1024)
            .map(|i| 1.0 + 2.0 * (2.0 * std::f64::consts::PI * f0 * i as f64 * dt).sin())
            .collect();
        let spec = super::amplitude_spectrum(&s, dt);
        let (f, a) = spec
            .iter()
            .copied()
            .max_by(|p, q| p.1.total_cmp(&q.1))
            .unwrap();
        assert!((f - f0).abs() < 1e-9, "{f} vs {f0}");
        assert!((a - 2.0).abs() < 1e-9, "{a}");
    }
}
