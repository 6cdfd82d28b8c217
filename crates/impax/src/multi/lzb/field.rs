//! The right-hand side in the contact-force time `τ` (`dp_nj = F_j dτ`):
//!
//! ```text
//! dp_nj/dτ = F_j = κ_j s_j^η                           (0 while the contact is off)
//! ds_j/dτ  = −v_nj (compression),  −v_nj / e_j² (expansion),  0 (off)
//! dp_tj/dτ = −μ_j σ_j F_j (slip),  x_j (stick: W_SS^tt x_S = −r_S, least norm),  0 (off)
//! dw_tj/dτ = v_tj dp_tj/dτ
//! v = v⁻ + W p.
//! ```
//!
//! `r_S` is the rate of change of the sticking contacts' tangential velocities due to every
//! other impulse rate: `r_a = Σ_c W_{t_a n_c} F_c + Σ_{c ∉ S} W_{t_a t_c} dp_tc/dτ`.
//!
//! The tangential rates are linear in the normal forces, `dp_t/dτ = T F`, with `T` fixed by
//! the regimes: the integration builds `T` once per set of regimes ([`Field`]), and the
//! right-hand side is then a product by `W` and one by `T`.

use super::state::{Modes, Normal, Setup, Tangent, MAXK, PER, PN, PT, S, WT};

/// The quantities of one point of the path: the contact velocities, the normal forces and the
/// tangential impulse rates.
#[derive(Debug, Clone, Copy)]
pub(super) struct Eval {
    /// `v = v⁻ + W p`.
    pub v: [f64; 2 * MAXK],
    /// `F_j = dp_nj/dτ`.
    pub f: [f64; MAXK],
    /// `dp_tj/dτ`.
    pub pt: [f64; MAXK],
}

/// Call `$f::<N>` with `N = 4K` the state's size for the problem's `K` (the loops over the
/// contacts then have their lengths at compile time).
macro_rules! by_size {
    ($k:expr, $f:ident ( $($arg:expr),* )) => {
        match $k {
            1 => $f::<4>($($arg),*),
            2 => $f::<8>($($arg),*),
            3 => $f::<12>($($arg),*),
            4 => $f::<16>($($arg),*),
            5 => $f::<20>($($arg),*),
            6 => $f::<24>($($arg),*),
            7 => $f::<28>($($arg),*),
            _ => $f::<32>($($arg),*),
        }
    };
}

/// The tangential impulse rates given the normal forces `f`: slip `−μ σ F`, stick by the
/// stick set's least-norm solve.
pub(super) fn tangential_rates(setup: &Setup, modes: &Modes, f: &[f64; MAXK]) -> [f64; MAXK] {
    by_size!(setup.k, tangential_rates_n(setup, modes, f))
}

/// [`tangential_rates`] for the state's size `N = 4K`.
#[inline(always)]
pub(super) fn tangential_rates_n<const N: usize>(
    setup: &Setup,
    modes: &Modes,
    f: &[f64; MAXK],
) -> [f64; MAXK] {
    debug_assert_eq!(N, PER * setup.k);
    let k = N / PER;
    let mut pt = [0.0; MAXK];
    for j in 0..k {
        if let (true, Tangent::Slip(sigma)) = (modes.active(j), modes.tangent[j]) {
            pt[j] = -setup.mu[j] * sigma * f[j];
        }
    }
    let st = &modes.stick;
    let n = st.n;
    if n > 0 {
        // (Stick contacts have no rate yet: pt is zero there.)
        let mut q = [0.0; 2 * MAXK];
        for c in 0..k {
            q[2 * c] = pt[c];
            q[2 * c + 1] = f[c];
        }
        let mut r = [0.0; MAXK];
        for (ra, &a) in r.iter_mut().zip(&st.idx[..n]) {
            *ra = dot(&setup.w[2 * a][..2 * k], &q[..2 * k]);
        }
        for (row, &a) in st.pinv.iter().zip(&st.idx[..n]) {
            pt[a] = -dot(&row[..n], &r[..n]);
        }
    }
    pt
}

/// `Σ a_i b_i`.
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The velocities, forces and tangential rates at the state `y`.
pub(super) fn eval(setup: &Setup, modes: &Modes, y: &[f64]) -> Eval {
    by_size!(setup.k, eval_n(setup, modes, y))
}

/// [`eval`] for the state's size `N = 4K`.
#[inline(always)]
pub(super) fn eval_n<const N: usize>(setup: &Setup, modes: &Modes, y: &[f64]) -> Eval {
    debug_assert_eq!(N, PER * setup.k);
    let k = N / PER;
    let n = 2 * k;
    let mut p = [0.0; 2 * MAXK];
    for c in 0..k {
        p[2 * c] = y[PER * c + PT];
        p[2 * c + 1] = y[PER * c + PN];
    }
    let mut v = [0.0; 2 * MAXK];
    for ((vi, row), v0) in v.iter_mut().zip(&setup.w[..n]).zip(&setup.v0[..n]) {
        *vi = v0 + dot(&row[..n], &p[..n]);
    }
    let mut f = [0.0; MAXK];
    for (j, fj) in f.iter_mut().enumerate().take(k) {
        if modes.active(j) {
            *fj = setup.force(j, y[PER * j + S]);
        }
    }
    let pt = tangential_rates_n::<N>(setup, modes, &f);
    Eval { v, f, pt }
}

/// The rates of change of the tangential velocities, `dv_t/dτ = (W dp/dτ)_t`, given the
/// normal forces `f` and the tangential rates `pt`.
#[inline]
pub(super) fn tangential_acceleration(
    setup: &Setup,
    f: &[f64; MAXK],
    pt: &[f64; MAXK],
) -> [f64; MAXK] {
    let k = setup.k;
    let mut a = [0.0; MAXK];
    for (j, aj) in a.iter_mut().enumerate().take(k) {
        let row = &setup.w[2 * j];
        let mut x = 0.0;
        for c in 0..k {
            x += row[2 * c] * pt[c] + row[2 * c + 1] * f[c];
        }
        *aj = x;
    }
    a
}

/// The right-hand side of one set of regimes, built once for the integration between two
/// events: each contact's deflection rate and the map `T` from the normal forces to the
/// tangential impulse rates (`dp_t/dτ = T F`: slip `T_jj = −μ_j σ_j`; stick
/// `T_S = −(W_SS^tt)⁺ W_S: (the tangential rows of the sticking contacts against every
/// contact's normal force and slip friction)`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Field {
    /// Whether each contact carries a force.
    active: [bool; MAXK],
    /// `ds_j/dτ = −v_nj / div_j` while active (`div = 1` in compression, `e_j²` in
    /// expansion).
    div: [f64; MAXK],
    /// `T`.
    map: [[f64; MAXK]; MAXK],
    /// Whether each contact slips with friction (`T_jj ≠ 0` its only entry): the contacts
    /// whose friction does work (a sticking contact's `v_t` is zero).
    rubs: [bool; MAXK],
}

impl Field {
    /// The field of the regimes `modes`.
    #[allow(clippy::needless_range_loop)] // j and c index the contacts' arrays alike
    pub(super) fn new(setup: &Setup, modes: &Modes) -> Field {
        let k = setup.k;
        let mut field = Field {
            active: [false; MAXK],
            div: [1.0; MAXK],
            map: [[0.0; MAXK]; MAXK],
            rubs: [false; MAXK],
        };
        // The slip friction per unit normal force (0 off or in stick).
        let mut slip = [0.0; MAXK];
        for j in 0..k {
            field.active[j] = modes.active(j);
            if modes.normal[j] == Normal::Expansion {
                field.div[j] = setup.e[j] * setup.e[j];
            }
            if let (true, Tangent::Slip(sigma)) = (modes.active(j), modes.tangent[j]) {
                slip[j] = -setup.mu[j] * sigma;
                field.map[j][j] = slip[j];
                field.rubs[j] = slip[j] != 0.0;
            }
        }
        let st = &modes.stick;
        let n = st.n;
        if n > 0 {
            // r = R F with R_ac = W_{t_a t_c} slip_c + W_{t_a n_c}; x_S = −(W_SS^tt)⁺ r.
            let mut r = [[0.0; MAXK]; MAXK];
            for (ra, &a) in r.iter_mut().zip(&st.idx[..n]) {
                let row = &setup.w[2 * a];
                for c in 0..k {
                    if modes.active(c) {
                        ra[c] = row[2 * c] * slip[c] + row[2 * c + 1];
                    }
                }
            }
            for (row, &a) in st.pinv.iter().zip(&st.idx[..n]) {
                for c in 0..k {
                    field.map[a][c] = -(0..n).map(|b| row[b] * r[b][c]).sum::<f64>();
                }
            }
        }
        field
    }

    /// The tangential impulse rates `T f` for the normal forces `f` (of the first `k`
    /// contacts).
    pub(super) fn tangential(&self, k: usize, f: &[f64; MAXK]) -> [f64; MAXK] {
        let mut pt = [0.0; MAXK];
        for (ptj, row) in pt.iter_mut().zip(&self.map).take(k) {
            *ptj = dot(&row[..k], &f[..k]);
        }
        pt
    }

    /// Whether contact `j` carries a force.
    #[inline(always)]
    pub(super) fn active(&self, j: usize) -> bool {
        self.active[j]
    }

    /// Row `j` of `T` (contact `j`'s tangential impulse rate per unit normal force of each
    /// contact).
    #[inline(always)]
    pub(super) fn map_row(&self, j: usize) -> &[f64; MAXK] {
        &self.map[j]
    }

    /// Whether contact `j` slips with friction.
    #[inline(always)]
    pub(super) fn rubs(&self, j: usize) -> bool {
        self.rubs[j]
    }

    /// Contact `j`'s divisor of the deflection rate, `ds_j/dτ = −v_nj / div_j` (1 in
    /// compression, `e_j²` in expansion).
    pub(super) fn div(&self, j: usize) -> f64 {
        self.div[j]
    }

    /// The velocities, forces and tangential rates at the state `y` (`N = 4K`).
    #[inline(always)]
    pub(super) fn eval<const N: usize>(&self, setup: &Setup, y: &[f64]) -> Eval {
        debug_assert_eq!(N, PER * setup.k);
        let k = N / PER;
        let n = 2 * k;
        let mut p = [0.0; 2 * MAXK];
        for c in 0..k {
            p[2 * c] = y[PER * c + PT];
            p[2 * c + 1] = y[PER * c + PN];
        }
        let mut v = [0.0; 2 * MAXK];
        for ((vi, row), v0) in v.iter_mut().zip(&setup.w[..n]).zip(&setup.v0[..n]) {
            *vi = v0 + dot(&row[..n], &p[..n]);
        }
        let mut f = [0.0; MAXK];
        for (j, fj) in f.iter_mut().enumerate().take(k) {
            if self.active[j] {
                *fj = setup.force(j, y[PER * j + S]);
            }
        }
        let mut pt = [0.0; MAXK];
        for (ptj, row) in pt.iter_mut().zip(&self.map).take(k) {
            *ptj = dot(&row[..k], &f[..k]);
        }
        Eval { v, f, pt }
    }

    /// `dy/dτ` at the state `y` (`N = 4K`): [`Field::rates`] without the point's other
    /// quantities (the same operations).
    #[inline(always)]
    pub(super) fn dy<const N: usize>(&self, setup: &Setup, y: &[f64; N]) -> [f64; N] {
        debug_assert_eq!(N, PER * setup.k);
        let k = N / PER;
        let n = 2 * k;
        let mut p = [0.0; 2 * MAXK];
        let mut f = [0.0; MAXK];
        for c in 0..k {
            p[2 * c] = y[PER * c + PT];
            p[2 * c + 1] = y[PER * c + PN];
            if self.active[c] {
                f[c] = setup.force(c, y[PER * c + S]);
            }
        }
        let mut dy = [0.0; N];
        for j in 0..k {
            let vt = setup.v0[2 * j] + dot(&setup.w[2 * j][..n], &p[..n]);
            let pt = dot(&self.map[j][..k], &f[..k]);
            let o = PER * j;
            dy[o + PT] = pt;
            dy[o + PN] = f[j];
            dy[o + S] = if self.active[j] {
                -(setup.v0[2 * j + 1] + dot(&setup.w[2 * j + 1][..n], &p[..n])) / self.div[j]
            } else {
                0.0
            };
            dy[o + WT] = vt * pt;
        }
        dy
    }

    /// Contact `j`'s normal velocity at the state `y` (`N = 4K`), as [`Field::eval`] gives
    /// it.
    #[inline(always)]
    pub(super) fn normal_velocity<const N: usize>(
        &self,
        setup: &Setup,
        y: &[f64; N],
        j: usize,
    ) -> f64 {
        let k = N / PER;
        let n = 2 * k;
        let mut p = [0.0; 2 * MAXK];
        for c in 0..k {
            p[2 * c] = y[PER * c + PT];
            p[2 * c + 1] = y[PER * c + PN];
        }
        setup.v0[2 * j + 1] + dot(&setup.w[2 * j + 1][..n], &p[..n])
    }

    /// `dy/dτ` at the state `y` (`N = 4K`) and the quantities of the point.
    #[inline(always)]
    pub(super) fn rates<const N: usize>(&self, setup: &Setup, y: &[f64; N]) -> ([f64; N], Eval) {
        let ev = self.eval::<N>(setup, y);
        let mut dy = [0.0; N];
        for j in 0..N / PER {
            let o = PER * j;
            dy[o + PT] = ev.pt[j];
            dy[o + PN] = ev.f[j];
            dy[o + S] = if self.active[j] {
                -ev.v[2 * j + 1] / self.div[j]
            } else {
                0.0
            };
            dy[o + WT] = ev.v[2 * j] * ev.pt[j];
        }
        (dy, ev)
    }
}
