//! An allocation-free Dormand–Prince 5(4) step on fixed-size arrays.
//!
//! Dormand & Prince, *A family of embedded Runge–Kutta formulae*, J. Comp. Appl. Math. 6
//! (1980); the fifth-order solution is propagated (local extrapolation), the embedded
//! fourth-order one gives the error estimate. Event location re-steps from the step's start
//! with a shorter step, so every event lies on the discrete solution itself.

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// Error weights b − b̂ (b̂ the fourth-order weights; the seventh stage is the FSAL stage).
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

#[inline(always)]
fn comb<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = *y;
    for (c, k) in terms {
        let hc = h * c;
        for i in 0..N {
            out[i] += hc * k[i];
        }
    }
    out
}

/// One Dormand–Prince step of size `h` from `(x, y)` with derivative `k1 = f(x, y)`.
/// Returns the fifth-order solution, its derivative (the FSAL stage) and the error estimate.
#[inline]
pub(crate) fn dopri_step<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    x: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
) -> ([f64; N], [f64; N], [f64; N]) {
    let k2 = f(x + C2 * h, &comb(y, h, &[(A21, k1)]));
    let k3 = f(x + C3 * h, &comb(y, h, &[(A31, k1), (A32, &k2)]));
    let k4 = f(
        x + C4 * h,
        &comb(y, h, &[(A41, k1), (A42, &k2), (A43, &k3)]),
    );
    let k5 = f(
        x + C5 * h,
        &comb(y, h, &[(A51, k1), (A52, &k2), (A53, &k3), (A54, &k4)]),
    );
    let k6 = f(
        x + h,
        &comb(
            y,
            h,
            &[(A61, k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
        ),
    );
    let y1 = comb(
        y,
        h,
        &[(B1, k1), (B3, &k3), (B4, &k4), (B5, &k5), (B6, &k6)],
    );
    let k7 = f(x + h, &y1);
    let mut err = [0.0; N];
    for i in 0..N {
        err[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
    }
    (y1, k7, err)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fifth_order_on_a_smooth_problem() {
        // y' = y cos x, y(0) = 1: y = exp(sin x).
        let f = |x: f64, y: &[f64; 1]| [y[0] * x.cos()];
        let run = |n: usize| {
            let h = 2.0 / n as f64;
            let (mut x, mut y) = (0.0, [1.0]);
            let mut k = f(x, &y);
            for _ in 0..n {
                let (y1, k1, _) = dopri_step(&f, x, &y, &k, h);
                y = y1;
                k = k1;
                x += h;
            }
            (y[0] - 2f64.sin().exp()).abs()
        };
        let (e1, e2) = (run(20), run(40));
        let order = (e1 / e2).log2();
        assert!(order > 4.7 && order < 6.5, "observed order {order}");
    }
}
