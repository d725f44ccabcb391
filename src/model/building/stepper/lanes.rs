//! Sums and updates four values at a time: over a tall building's modes (mode k in lane k mod 4,
//! a sum's lanes joined pairwise), over the rows of a table, over a slab's tabulated points, or
//! over the four products of a mode's exact map. Where the processor has AVX, the four lanes are
//! one 256-bit register ([`avx::V4`], its operations written out, since the compiler left loops
//! written lane by lane half in scalar registers); elsewhere four scalars ([`F4`]). Either way
//! the same multiplications, divisions and additions in the same lanes (Rust never fuses them),
//! so the same bits on every processor (tested against the formulas written out).

use super::super::modal::Propagator;

/// Modes from which a side's sums are taken in lanes; a few modes' sum is taken in order, the
/// cheapest there.
pub(super) const LANES_FROM: usize = 16;

/// `fn name(args) -> R` that calls `generic::<L>(args)` (`#[inline(always)]`, so compiled into
/// each caller) with four modes a value: one AVX register ([`avx::V4`]) where the processor has
/// it, four scalars ([`F4`]) elsewhere; the same operations lane by lane either way.
macro_rules! in_lanes {
    ($(#[$m:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? = $generic:ident) => {
        $(#[$m])*
        #[inline(never)]
        $vis fn $name($($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx") {
                #[target_feature(enable = "avx")]
                fn with_avx($($arg: $ty),*) $(-> $ret)? {
                    $generic::<avx::V4>($($arg),*)
                }
                // SAFETY: the processor has just been found to have AVX.
                return unsafe { with_avx($($arg),*) };
            }
            // Out of line, so that this function stays a test and a jump: the four scalars'
            // loop, inlined here, made it save and restore six registers on every call.
            #[inline(never)]
            fn in_scalars($($arg: $ty),*) $(-> $ret)? {
                $generic::<F4>($($arg),*)
            }
            in_scalars($($arg),*)
        }
    };
}

/// x's first `full` values (a multiple of four) as four-mode chunks: a loop over
/// `0..full / 4` indexes every such slice in bounds, which the compiler sees (it does not see
/// that 4 c + 4 <= full from c < full / 4, and kept a bounds check per slice in the loop).
#[inline(always)]
fn quads(x: &[f64], full: usize) -> &[[f64; 4]] {
    x[..full].as_chunks().0
}

/// [`quads`] of a slice written to.
#[inline(always)]
fn quads_mut(x: &mut [f64], full: usize) -> &mut [[f64; 4]] {
    x[..full].as_chunks_mut().0
}

/// Four lanes joined pairwise.
#[inline(always)]
fn join(l: [f64; 4]) -> f64 {
    (l[0] + l[2]) + (l[1] + l[3])
}

/// Where a sum's main loop stops: its sixteen-mode blocks (four chunks a turn, so that the
/// loop's count and test are paid once per sixteen modes), then four-mode chunks up to `full`.
/// The chunks of each block are read in order, so each lane's terms are added in the modes'
/// order either way.
const BLOCK: usize = 16;

/// The first mode of each of a block's four-mode chunks.
const IN_BLOCK: [usize; 4] = [0, 4, 8, 12];

in_lanes! {
    /// The sum of c q (q at least as long as c).
    pub(super) fn dot(c: &[f64], q: &[f64]) -> f64 = dot_in
}

#[inline(always)]
fn dot_in<L: Four>(c: &[f64], q: &[f64]) -> f64 {
    let n = c.len();
    let q = &q[..n];
    let (full, big) = (n - n % 4, n - n % BLOCK);
    let mut u = L::splat(0.0);
    for (c, q) in c[..big]
        .chunks_exact(BLOCK)
        .zip(q[..big].chunks_exact(BLOCK))
    {
        for j in IN_BLOCK {
            u = u + L::at(c, j) * L::at(q, j);
        }
    }
    for (c, q) in c[big..full]
        .chunks_exact(4)
        .zip(q[big..full].chunks_exact(4))
    {
        u = u + L::at(c, 0) * L::at(q, 0);
    }
    let mut u = u.array();
    for k in full..n {
        u[k - full] += c[k] * q[k];
    }
    join(u)
}

in_lanes! {
    /// The sum of c (q + d) (q and d at least as long as c): each term's sum q + d first, as a
    /// state moved by an increment is.
    pub(super) fn dot_moved(c: &[f64], q: &[f64], d: &[f64]) -> f64 = dot_moved_in
}

#[inline(always)]
fn dot_moved_in<L: Four>(c: &[f64], q: &[f64], d: &[f64]) -> f64 {
    let n = c.len();
    let (q, d) = (&q[..n], &d[..n]);
    let (full, big) = (n - n % 4, n - n % BLOCK);
    let mut u = L::splat(0.0);
    let blocks = c[..big]
        .chunks_exact(BLOCK)
        .zip(q[..big].chunks_exact(BLOCK))
        .zip(d[..big].chunks_exact(BLOCK));
    for ((c, q), d) in blocks {
        for j in IN_BLOCK {
            u = u + L::at(c, j) * (L::at(q, j) + L::at(d, j));
        }
    }
    let chunks = c[big..full]
        .chunks_exact(4)
        .zip(q[big..full].chunks_exact(4))
        .zip(d[big..full].chunks_exact(4));
    for ((c, q), d) in chunks {
        u = u + L::at(c, 0) * (L::at(q, 0) + L::at(d, 0));
    }
    let mut u = u.array();
    for k in full..n {
        u[k - full] += c[k] * (q[k] + d[k]);
    }
    join(u)
}

in_lanes! {
    /// The sums of c q and of c v (q and v at least as long as c), each as [`dot`] takes it, in
    /// one pass: c read once for both.
    pub(super) fn dot2(c: &[f64], q: &[f64], v: &[f64]) -> (f64, f64) = dot2_in
}

#[inline(always)]
fn dot2_in<L: Four>(c: &[f64], q: &[f64], v: &[f64]) -> (f64, f64) {
    let n = c.len();
    let (q, v) = (&q[..n], &v[..n]);
    let (full, big) = (n - n % 4, n - n % BLOCK);
    let (mut u, mut r) = (L::splat(0.0), L::splat(0.0));
    let blocks = c[..big]
        .chunks_exact(BLOCK)
        .zip(q[..big].chunks_exact(BLOCK))
        .zip(v[..big].chunks_exact(BLOCK));
    for ((c, q), v) in blocks {
        for j in IN_BLOCK {
            let c = L::at(c, j);
            u = u + c * L::at(q, j);
            r = r + c * L::at(v, j);
        }
    }
    let chunks = c[big..full]
        .chunks_exact(4)
        .zip(q[big..full].chunks_exact(4))
        .zip(v[big..full].chunks_exact(4));
    for ((c, q), v) in chunks {
        let c = L::at(c, 0);
        u = u + c * L::at(q, 0);
        r = r + c * L::at(v, 0);
    }
    let (mut u, mut r) = (u.array(), r.array());
    for k in full..n {
        u[k - full] += c[k] * q[k];
        r[k - full] += c[k] * v[k];
    }
    (join(u), join(r))
}

in_lanes! {
    /// The sums of c q, c v and c a (q, v and a at least as long as c), each as [`dot`] takes
    /// it, in one pass: c read once for the three (a free stretch reads a point's or a signal's
    /// value, rate and acceleration together).
    pub(super) fn dot3(c: &[f64], q: &[f64], v: &[f64], a: &[f64]) -> [f64; 3] = dot3_in
}

#[inline(always)]
fn dot3_in<L: Four>(c: &[f64], q: &[f64], v: &[f64], a: &[f64]) -> [f64; 3] {
    let n = c.len();
    let (q, v, a) = (&q[..n], &v[..n], &a[..n]);
    let (full, big) = (n - n % 4, n - n % BLOCK);
    let mut sums = [L::splat(0.0); 3];
    let blocks = c[..big]
        .chunks_exact(BLOCK)
        .zip(q[..big].chunks_exact(BLOCK))
        .zip(v[..big].chunks_exact(BLOCK))
        .zip(a[..big].chunks_exact(BLOCK));
    for (((c, q), v), a) in blocks {
        for j in IN_BLOCK {
            add3(&mut sums, [c, q, v, a], j);
        }
    }
    let chunks = c[big..full]
        .chunks_exact(4)
        .zip(q[big..full].chunks_exact(4))
        .zip(v[big..full].chunks_exact(4))
        .zip(a[big..full].chunks_exact(4));
    for (((c, q), v), a) in chunks {
        add3(&mut sums, [c, q, v, a], 0);
    }
    let mut sums = sums.map(L::array);
    for k in full..n {
        let l = k - full;
        sums[0][l] += c[k] * q[k];
        sums[1][l] += c[k] * v[k];
        sums[2][l] += c[k] * a[k];
    }
    sums.map(join)
}

/// One chunk's terms of [`dot3`]'s sums, the chunk at j of each of c, q, v and a.
#[inline(always)]
fn add3<L: Four>(sums: &mut [L; 3], [c, q, v, a]: [&[f64]; 4], j: usize) {
    let c = L::at(c, j);
    sums[0] = sums[0] + c * L::at(q, j);
    sums[1] = sums[1] + c * L::at(v, j);
    sums[2] = sums[2] + c * L::at(a, j);
}

in_lanes! {
    /// A table's four weighted sums for every row: out[b][j] = the sum over the modes k of
    /// abs[k rows + j] m[b][k], from zero, mode after mode (as each row's own sum takes them,
    /// bit for bit). Eight rows' sums stay in registers over all the modes, so the rows are
    /// neither read nor written once per mode. `abs` holds
    /// m[b].len() modes of `rows` rows; each out[b] is `rows` long.
    pub(super) fn weigh_rows(abs: &[f64], rows: usize, m: [&[f64]; 4], out: [&mut [f64]; 4]) = weigh_rows_in
}

#[inline(always)]
fn weigh_rows_in<L: Four>(abs: &[f64], rows: usize, m: [&[f64]; 4], out: [&mut [f64]; 4]) {
    let modes = m[0].len();
    let [m0, m1, m2, m3] = m.map(|m| &m[..modes]);
    let abs = &abs[..modes * rows];
    let [o0, o1, o2, o3] = out;
    let (o0, o1, o2, o3) = (
        &mut o0[..rows],
        &mut o1[..rows],
        &mut o2[..rows],
        &mut o3[..rows],
    );
    let (pairs, full) = (rows - rows % 8, rows - rows % 4);
    let zero = L::splat(0.0);
    let mut j = 0;
    // Eight rows at a time, each of their sums a named value (the compiler kept an array of
    // them in memory): the four weights are splat once for the eight.
    while j < pairs {
        let (mut a0, mut a1, mut a2, mut a3) = (zero, zero, zero, zero);
        let (mut b0, mut b1, mut b2, mut b3) = (zero, zero, zero, zero);
        for (k, table) in abs.chunks_exact(rows).enumerate() {
            let (w0, w1, w2, w3) = (
                L::splat(m0[k]),
                L::splat(m1[k]),
                L::splat(m2[k]),
                L::splat(m3[k]),
            );
            let eight = &table[j..j + 8];
            let (x, y) = (L::at(eight, 0), L::at(eight, 4));
            a0 = a0 + x * w0;
            a1 = a1 + x * w1;
            a2 = a2 + x * w2;
            a3 = a3 + x * w3;
            b0 = b0 + y * w0;
            b1 = b1 + y * w1;
            b2 = b2 + y * w2;
            b3 = b3 + y * w3;
        }
        a0.put(o0, j);
        a1.put(o1, j);
        a2.put(o2, j);
        a3.put(o3, j);
        b0.put(o0, j + 4);
        b1.put(o1, j + 4);
        b2.put(o2, j + 4);
        b3.put(o3, j + 4);
        j += 8;
    }
    if j < full {
        let (mut a0, mut a1, mut a2, mut a3) = (zero, zero, zero, zero);
        for k in 0..modes {
            let x = L::at(abs, k * rows + j);
            a0 = a0 + x * L::splat(m0[k]);
            a1 = a1 + x * L::splat(m1[k]);
            a2 = a2 + x * L::splat(m2[k]);
            a3 = a3 + x * L::splat(m3[k]);
        }
        a0.put(o0, j);
        a1.put(o1, j);
        a2.put(o2, j);
        a3.put(o3, j);
        j += 4;
    }
    for row in j..rows {
        let mut sums = [0.0; 4];
        for k in 0..modes {
            let a = abs[k * rows + row];
            sums[0] += a * m0[k];
            sums[1] += a * m1[k];
            sums[2] += a * m2[k];
            sums[3] += a * m3[k];
        }
        (o0[row], o1[row], o2[row], o3[row]) = (sums[0], sums[1], sums[2], sums[3]);
    }
}

in_lanes! {
    /// sums += r force, mode by mode (r at least as long as sums).
    pub(super) fn add_scaled(sums: &mut [f64], r: &[f64], force: f64) = add_scaled_in
}

#[inline(always)]
fn add_scaled_in<L: Four>(sums: &mut [f64], r: &[f64], force: f64) {
    let n = sums.len();
    let r = &r[..n];
    let full = n - n % 4;
    let f = L::splat(force);
    for (s, r) in sums[..full]
        .chunks_exact_mut(4)
        .zip(r[..full].chunks_exact(4))
    {
        (L::at(s, 0) + L::at(r, 0) * f).put(s, 0);
    }
    for k in full..n {
        sums[k] += r[k] * force;
    }
}

in_lanes! {
    /// Each mode's increment with the contact forces: `load` holds the sum f of the forces'
    /// loads (without the side's sign); dq = step + sign f / k_hat, and the load becomes sign f
    /// (+ 0.0 makes a zero positive, as a sum from +0 is).
    pub(super) fn with_forces(dq: &mut [f64], load: &mut [f64], step: &[f64], k_hat: &[f64], sign: f64) = with_forces_in
}

#[inline(always)]
fn with_forces_in<L: Four>(
    dq: &mut [f64],
    load: &mut [f64],
    step: &[f64],
    k_hat: &[f64],
    sign: f64,
) {
    let n = k_hat.len();
    let (dq, load, step) = (&mut dq[..n], &mut load[..n], &step[..n]);
    let full = n - n % 4;
    {
        let (step, k_hat) = (quads(step, full), quads(k_hat, full));
        let (dq, load) = (quads_mut(dq, full), quads_mut(load, full));
        for c in 0..full / 4 {
            let f = L::at(&load[c], 0);
            let (d, l) = with_force(L::at(&step[c], 0), f, L::at(&k_hat[c], 0), sign);
            d.put(&mut dq[c], 0);
            l.put(&mut load[c], 0);
        }
    }
    for k in full..n {
        (dq[k], load[k]) = with_force(step[k], load[k], k_hat[k], sign);
    }
}

in_lanes! {
    /// [`with_forces`] where one point pushes, with `force`, through its projections `r`: each
    /// mode's sum of the forces' loads is 0 + r force, as [`add_scaled`] makes it from a cleared
    /// sum, taken in the same pass (r at least as long as k_hat).
    pub(super) fn with_one_force(dq: &mut [f64], load: &mut [f64], step: &[f64], k_hat: &[f64], r: &[f64], force: f64, sign: f64) = with_one_force_in
}

#[inline(always)]
fn with_one_force_in<L: Four>(
    dq: &mut [f64],
    load: &mut [f64],
    step: &[f64],
    k_hat: &[f64],
    r: &[f64],
    force: f64,
    sign: f64,
) {
    let n = k_hat.len();
    let (dq, load, step, r) = (&mut dq[..n], &mut load[..n], &step[..n], &r[..n]);
    let full = n - n % 4;
    let (zero, f) = (L::splat(0.0), L::splat(force));
    {
        let (step, k_hat, r) = (quads(step, full), quads(k_hat, full), quads(r, full));
        let (dq, load) = (quads_mut(dq, full), quads_mut(load, full));
        for c in 0..full / 4 {
            let sum = zero + L::at(&r[c], 0) * f;
            let (d, l) = with_force(L::at(&step[c], 0), sum, L::at(&k_hat[c], 0), sign);
            d.put(&mut dq[c], 0);
            l.put(&mut load[c], 0);
        }
    }
    for k in full..n {
        (dq[k], load[k]) = with_force(step[k], 0.0 + r[k] * force, k_hat[k], sign);
    }
}

/// A mode's increment with the contact forces' load f (summed without the side's sign) and
/// that load: step + sign f / k_hat, and sign f (+ 0.0 makes a zero positive, as a sum from +0
/// is).
#[inline(always)]
pub(super) fn with_force<T: Lane>(step: T, f: T, k_hat: T, sign: f64) -> (T, T) {
    let sign = T::splat(sign);
    (step + sign * f / k_hat, sign * f + T::splat(0.0))
}

/// Each mode's exact state j fine steps into a free stretch from `y0` (per mode [q(0), q'(0),
/// g(0), g']) by its map (`maps`, the weights giving q and q'), and its acceleration there,
/// y2 + y3 s - c v - w2 q (`damping` c = 2 zeta omega, `stiffness` w2 = omega^2, s = j h). A
/// map's four products are summed in pairs, (a0 b0 + a1 b1) + (a2 b2 + a3 b3), as
/// [`Propagator::apply`] sums them; where the processor has AVX, a mode's four products are one
/// register, added by the same pairs.
pub(super) struct Exact<'a> {
    pub maps: &'a [Propagator],
    pub y0: &'a [[f64; 4]],
    pub damping: &'a [f64],
    pub stiffness: &'a [f64],
    pub s: f64,
}

in_lanes! {
    /// [`Exact`]'s states and accelerations, mode by mode.
    pub(super) fn exact_states(e: &Exact, q: &mut [f64], v: &mut [f64], acc: &mut [f64]) = exact_states_in
}

#[inline(always)]
fn exact_states_in<L: Four>(e: &Exact, q: &mut [f64], v: &mut [f64], acc: &mut [f64]) {
    let n = q.len();
    let (v, acc) = (&mut v[..n], &mut acc[..n]);
    let (maps, y0) = (&e.maps[..n], &e.y0[..n]);
    let (damping, stiffness) = (&e.damping[..n], &e.stiffness[..n]);
    for k in 0..n {
        let (qk, vk) = L::apply(&maps[k], &y0[k]);
        q[k] = qk;
        v[k] = vk;
        acc[k] = acceleration(&y0[k], e.s, damping[k], stiffness[k], qk, vk);
    }
}

/// A mode's acceleration from the equation of motion at s into a free stretch from y0 (its
/// forcing g + g' s), with its displacement q and velocity v there (`damping` 2 zeta omega,
/// `stiffness` omega^2).
#[inline(always)]
pub(super) fn acceleration(
    y0: &[f64; 4],
    s: f64,
    damping: f64,
    stiffness: f64,
    q: f64,
    v: f64,
) -> f64 {
    y0[2] + y0[3] * s - damping * v - stiffness * q
}

/// [`stencil`](crate::model::ringing::stencil) on four values a lane: each lane's four samples
/// `s`, summed in the same pairs.
#[inline(always)]
fn stencil_in<T: Lane>(w: &[f64; 4], s: [T; 4]) -> T {
    (T::splat(w[0]) * s[0] + T::splat(w[1]) * s[1])
        + (T::splat(w[2]) * s[2] + T::splat(w[3]) * s[3])
}

/// The four samples each of four consecutive points' stencils reads, from `src[k..k + 7]`.
#[inline(always)]
fn shifted<L: Four>(src: &[f64], k: usize) -> [L; 4] {
    std::array::from_fn(|j| L::at(src, k + j))
}

in_lanes! {
    /// A slab's ringing Q over a block of points that reads only points before it:
    /// todo[k] = (a[k] + round stencil(w, src[k..k + 4])) gain (src at least todo's length + 3).
    pub(in crate::model::building) fn ringing_block(todo: &mut [f64], a: &[f64], src: &[f64], w: &[f64; 4], round: f64, gain: f64) = ringing_block_in
}

#[inline(always)]
fn ringing_block_in<L: Four>(
    todo: &mut [f64],
    a: &[f64],
    src: &[f64],
    w: &[f64; 4],
    round: f64,
    gain: f64,
) {
    let n = todo.len();
    let (a, src) = (&a[..n], &src[..n + 3]);
    let full = n - n % 4;
    let (round_l, gain_l) = (L::splat(round), L::splat(gain));
    // Indexed by chunk, not `step_by` (see `quads`); the stencils read past a chunk, so the
    // sources stay whole slices.
    for chunk in 0..full / 4 {
        let k = 4 * chunk;
        let read = stencil_in(w, shifted::<L>(src, k));
        ((L::at(a, k) + round_l * read) * gain_l).put(todo, k);
    }
    for k in full..n {
        let s = &src[k..k + 4];
        todo[k] = (a[k] + round * stencil_in(w, [s[0], s[1], s[2], s[3]])) * gain;
    }
}

/// What a slab's elastic displacement is made of at each tabulated point: its two look-ups'
/// samples and weights, the newest Q, B, and the slab's constants [near weight, far weight,
/// 1 / Z, the newest Q's share, 1 / m].
pub(in crate::model::building) struct Elastic<'a> {
    pub near: (&'a [f64], &'a [f64; 4]),
    pub far: (&'a [f64], &'a [f64; 4]),
    pub newest: &'a [f64],
    pub b: &'a [f64],
    pub constants: [f64; 5],
}

in_lanes! {
    /// e at each point: 1/Z (near weight stencil(near) + far weight stencil(far) + top newest)
    /// - B / m, each look-up's samples from its slice at the point (as long as `out` + 3).
    pub(in crate::model::building) fn elastic_rows(e: &Elastic, out: &mut [f64]) = elastic_rows_in
}

#[inline(always)]
fn elastic_rows_in<L: Four>(e: &Elastic, out: &mut [f64]) {
    let n = out.len();
    let (near, far) = (&e.near.0[..n + 3], &e.far.0[..n + 3]);
    let (newest, b) = (&e.newest[..n], &e.b[..n]);
    let [near_weight, far_weight, inv_z, top, inv_m] = e.constants;
    let full = n - n % 4;
    let [nw, fw, iz, tp, im] = e.constants.map(L::splat);
    // Indexed by chunk, as `ringing_block` is.
    for chunk in 0..full / 4 {
        let k = 4 * chunk;
        let near_far = nw * stencil_in(e.near.1, shifted::<L>(near, k))
            + fw * stencil_in(e.far.1, shifted::<L>(far, k));
        (iz * (near_far + tp * L::at(newest, k)) - im * L::at(b, k)).put(out, k);
    }
    for k in full..n {
        let (s, f) = (&near[k..k + 4], &far[k..k + 4]);
        let near_far = near_weight * stencil_in(e.near.1, [s[0], s[1], s[2], s[3]])
            + far_weight * stencil_in(e.far.1, [f[0], f[1], f[2], f[3]]);
        out[k] = inv_z * (near_far + top * newest[k]) - inv_m * b[k];
    }
}

/// A side's modes where a contact step starts, and what it moves them by.
pub(super) struct Ends<'a> {
    pub q0: &'a [f64],
    pub v0: &'a [f64],
    pub dq: &'a [f64],
    /// Each mode's omega, zeta and participation.
    pub coefficients: [&'a [f64]; 3],
    pub hh: f64,
    /// The ground's acceleration at both ends, summed.
    pub ground: f64,
}

/// What committing a contact step to a side's modes adds up, each sum in lanes.
pub(super) struct Committed {
    /// The ground's work and the damping's, by Newmark's discrete energy identity [J].
    pub input: f64,
    pub damping: f64,
    /// The sizes of dq and of the velocities at the end: [the sum of |x|, the Euclidean size].
    pub moved: [f64; 2],
    pub speed: [f64; 2],
}

in_lanes! {
    /// A contact step committed to a side's modes: q, v and a (holding the accelerations where
    /// it starts) at its end, by Newmark's average acceleration from the increments `e.dq`; the
    /// energy terms and sizes summed in lanes.
    pub(super) fn commit(e: &Ends, q: &mut [f64], v: &mut [f64], a: &mut [f64]) -> Committed = commit_in
}

#[inline(always)]
fn commit_in<L: Four>(e: &Ends, q: &mut [f64], v: &mut [f64], a: &mut [f64]) -> Committed {
    let n = e.dq.len();
    let (q0, v0s, dqs) = (&e.q0[..n], &e.v0[..n], &e.dq[..n]);
    let [omega, zeta, gamma] = e.coefficients.map(|c| &c[..n]);
    let (q, v, a) = (&mut q[..n], &mut v[..n], &mut a[..n]);
    let hh = e.hh;
    // Per lane: the ground's work, the damping's, |dq|, dq^2, |v1|, v1^2. Four modes at a time
    // as whole four-lane values, which the compiler keeps in vector registers (written lane by
    // lane inside one loop, it spilled them).
    let mut acc = [L::splat(0.0); 6];
    let full = n - n % 4;
    {
        let (q0, v0s, dqs) = (quads(q0, full), quads(v0s, full), quads(dqs, full));
        let [omega, zeta, gamma] = [omega, zeta, gamma].map(|x| quads(x, full));
        let (q, v, a) = (quads_mut(q, full), quads_mut(v, full), quads_mut(a, full));
        for c in 0..full / 4 {
            let (q0, v0, dq) = (L::at(&q0[c], 0), L::at(&v0s[c], 0), L::at(&dqs[c], 0));
            let mode = [&omega[c], &zeta[c], &gamma[c]].map(|x| L::at(x, 0));
            let (v1, a1) = newmark_end(dq, v0, L::at(&a[c], 0), hh);
            let (input, damping) = energy_terms(dq, v0, v1, mode, hh, e.ground);
            for (sum, term) in
                acc.iter_mut()
                    .zip([input, damping, dq.abs(), dq * dq, v1.abs(), v1 * v1])
            {
                *sum = *sum + term;
            }
            (q0 + dq).put(&mut q[c], 0);
            v1.put(&mut v[c], 0);
            a1.put(&mut a[c], 0);
        }
    }
    let mut acc = acc.map(L::array);
    for k in full..n {
        let l = k - full;
        let (v0, dq) = (v0s[k], dqs[k]);
        let (v1, a1) = newmark_end(dq, v0, a[k], hh);
        let (input, damping) =
            energy_terms(dq, v0, v1, [omega[k], zeta[k], gamma[k]], hh, e.ground);
        for (sum, term) in
            acc.iter_mut()
                .zip([input, damping, dq.abs(), dq * dq, v1.abs(), v1 * v1])
        {
            sum[l] += term;
        }
        q[k] = q0[k] + dq;
        v[k] = v1;
        a[k] = a1;
    }
    Committed {
        input: join(acc[0]),
        damping: join(acc[1]),
        moved: [join(acc[2]), join(acc[3]).sqrt()],
        speed: [join(acc[4]), join(acc[5]).sqrt()],
    }
}

/// Four modes' values, one a lane, in four scalars: each operation lane by lane, so the same
/// bits as four scalar ones. Where the processor has AVX, [`avx::V4`] takes its place.
#[derive(Clone, Copy)]
pub(super) struct F4([f64; 4]);

impl F4 {
    #[inline(always)]
    fn lanes(self, o: F4, f: impl Fn(f64, f64) -> f64) -> F4 {
        F4(std::array::from_fn(|l| f(self.0[l], o.0[l])))
    }
}

/// Four modes' values, read from and written to four consecutive modes.
pub(super) trait Four: Lane {
    fn at(x: &[f64], c: usize) -> Self;
    fn put(self, x: &mut [f64], c: usize);
    fn array(self) -> [f64; 4];
    /// [`Propagator::apply`], a mode's map on its state (a map's four products are what this
    /// type can hold at once).
    fn apply(p: &Propagator, y: &[f64; 4]) -> (f64, f64);
}

impl Four for F4 {
    #[inline(always)]
    fn at(x: &[f64], c: usize) -> F4 {
        F4(x[c..c + 4].try_into().expect("four"))
    }
    #[inline(always)]
    fn put(self, x: &mut [f64], c: usize) {
        x[c..c + 4].copy_from_slice(&self.0);
    }
    #[inline(always)]
    fn array(self) -> [f64; 4] {
        self.0
    }
    #[inline(always)]
    fn apply(p: &Propagator, y: &[f64; 4]) -> (f64, f64) {
        p.apply(y)
    }
}

/// Four lanes in one AVX register. Only made inside functions compiled for AVX, on a
/// processor found to have it.
#[cfg(target_arch = "x86_64")]
mod avx {
    use super::{Four, Lane};
    use std::arch::x86_64::*;

    #[derive(Clone, Copy)]
    pub struct V4(__m256d);

    impl Four for V4 {
        #[inline(always)]
        fn at(x: &[f64], c: usize) -> V4 {
            debug_assert!(std::arch::is_x86_feature_detected!("avx"));
            let x = &x[c..c + 4];
            // SAFETY: four f64 in bounds (just sliced); unaligned loads are allowed.
            V4(unsafe { _mm256_loadu_pd(x.as_ptr()) })
        }
        #[inline(always)]
        fn put(self, x: &mut [f64], c: usize) {
            let x = &mut x[c..c + 4];
            // SAFETY: as in `at`.
            unsafe { _mm256_storeu_pd(x.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn array(self) -> [f64; 4] {
            let mut out = [0.0; 4];
            self.put(&mut out, 0);
            out
        }
        /// The four products in one register: the pairs added by one horizontal addition,
        /// then the two pairs' sums.
        #[inline(always)]
        fn apply(p: &super::Propagator, y: &[f64; 4]) -> (f64, f64) {
            debug_assert!(std::arch::is_x86_feature_detected!("avx"));
            // SAFETY: only called from a function compiled for AVX, taken where the processor was
            // found to have it; four f64 in bounds each, unaligned loads allowed.
            unsafe {
                let y = _mm256_loadu_pd(y.as_ptr());
                let q = _mm256_mul_pd(_mm256_loadu_pd(p.q.as_ptr()), y);
                let v = _mm256_mul_pd(_mm256_loadu_pd(p.v.as_ptr()), y);
                // [q0 + q1, v0 + v1, q2 + q3, v2 + v3]
                let pairs = _mm256_hadd_pd(q, v);
                let sums = _mm_add_pd(
                    _mm256_castpd256_pd128(pairs),
                    _mm256_extractf128_pd(pairs, 1),
                );
                (
                    _mm_cvtsd_f64(sums),
                    _mm_cvtsd_f64(_mm_unpackhi_pd(sums, sums)),
                )
            }
        }
    }

    impl Lane for V4 {
        #[inline(always)]
        fn splat(x: f64) -> Self {
            debug_assert!(std::arch::is_x86_feature_detected!("avx"));
            // SAFETY (here and below): a V4 is only made (`at`, `splat`) inside the functions
            // `in_lanes!` compiles for AVX, taken only where the processor was found to have it:
            // nothing else in this file may name `avx::V4`.
            V4(unsafe { _mm256_set1_pd(x) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            // |x| clears the sign bit, as f64::abs does.
            V4(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
        }
    }

    macro_rules! v4_op {
        ($tr:ident, $f:ident, $intr:ident) => {
            impl std::ops::$tr for V4 {
                type Output = V4;
                #[inline(always)]
                fn $f(self, o: V4) -> V4 {
                    V4(unsafe { $intr(self.0, o.0) })
                }
            }
        };
    }
    v4_op!(Add, add, _mm256_add_pd);
    v4_op!(Sub, sub, _mm256_sub_pd);
    v4_op!(Mul, mul, _mm256_mul_pd);
    v4_op!(Div, div, _mm256_div_pd);

    impl std::ops::Neg for V4 {
        type Output = V4;
        #[inline(always)]
        fn neg(self) -> V4 {
            // -x flips the sign bit, as f64's negation does.
            V4(unsafe { _mm256_xor_pd(_mm256_set1_pd(-0.0), self.0) })
        }
    }
}

/// What Newmark's formulas need of a value: a mode's f64, or four modes' ([`F4`], [`avx::V4`]).
pub(super) trait Lane:
    Copy
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Div<Output = Self>
    + std::ops::Neg<Output = Self>
{
    fn splat(x: f64) -> Self;
    fn abs(self) -> Self;
}

impl Lane for f64 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
}

impl Lane for F4 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        F4([x; 4])
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F4(self.0.map(f64::abs))
    }
}

macro_rules! f4_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl std::ops::$tr for F4 {
            type Output = F4;
            #[inline(always)]
            fn $f(self, o: F4) -> F4 {
                self.lanes(o, |x, y| x $op y)
            }
        }
    };
}
f4_op!(Add, add, +);
f4_op!(Sub, sub, -);
f4_op!(Mul, mul, *);
f4_op!(Div, div, /);

impl std::ops::Neg for F4 {
    type Output = F4;
    #[inline(always)]
    fn neg(self) -> F4 {
        F4(self.0.map(|x| -x))
    }
}

/// What a tall elastic side's modes' increments over a whole grid step are made from.
pub(super) struct Increment<'a> {
    /// Each mode's omega, zeta and participation.
    pub coefficients: [&'a [f64]; 3],
    /// Each mode's velocity and acceleration where the step starts.
    pub v: &'a [f64],
    pub a: &'a [f64],
    /// Each mode's effective stiffness over a whole grid step.
    pub k_hat: &'a [f64],
    /// Each mode's load from the contact forces where the step starts.
    pub load_now: &'a [f64],
    pub hh: f64,
    pub ground_change: f64,
}

in_lanes! {
    /// Each mode's increment over the step without a change of the contact forces, into `step`:
    /// Newmark's incremental form, term by term as [`Stepper::free_increment`] takes it for a few
    /// modes (no sums across modes: the same bits in vector lanes).
    ///
    /// [`Stepper::free_increment`]: super::Stepper
    pub(super) fn increment(e: &Increment, step: &mut [f64]) = increment_in
}

#[inline(always)]
fn increment_in<L: Four>(e: &Increment, step: &mut [f64]) {
    let n = step.len();
    let [omega, zeta, gamma] = e.coefficients.map(|c| &c[..n]);
    let (v, a, k_hat, load_now) = (&e.v[..n], &e.a[..n], &e.k_hat[..n], &e.load_now[..n]);
    let hh = e.hh;
    let full = n - n % 4;
    {
        let [omega4, zeta4, gamma4] = [omega, zeta, gamma].map(|x| quads(x, full));
        let [v4, a4, k_hat4, now4] = [v, a, k_hat, load_now].map(|x| quads(x, full));
        let step4 = quads_mut(step, full);
        for c in 0..full / 4 {
            let mode = [&omega4[c], &zeta4[c], &gamma4[c]].map(|x| L::at(x, 0));
            // 0.0: an elastic side's corrections do not change.
            let (now, zero) = (L::at(&now4[c], 0), L::splat(0.0));
            let (vc, ac) = (L::at(&v4[c], 0), L::at(&a4[c], 0));
            let load = increment_load(mode, e.ground_change, now, zero, vc, ac, hh);
            (load / L::at(&k_hat4[c], 0)).put(&mut step4[c], 0);
        }
    }
    for k in full..n {
        let mode = [omega[k], zeta[k], gamma[k]];
        let load = increment_load(mode, e.ground_change, load_now[k], 0.0, v[k], a[k], hh);
        step[k] = load / k_hat[k];
    }
}

/// A mode's load in Newmark's incremental form, k_hat dq = dp + (4/h + 2c) v + 2a, over a step
/// of length hh: the ground's change (times the participation), the contact forces' load where
/// the step starts taken off, the yielding storeys' corrections' change, and the terms of the
/// velocity and acceleration where it starts. `[omega, zeta, gamma]` are the mode's.
#[inline(always)]
pub(super) fn increment_load<T: Lane>(
    [omega, zeta, gamma]: [T; 3],
    ground_change: f64,
    load_now: T,
    pseudo_change: T,
    v: T,
    a: T,
    hh: f64,
) -> T {
    let s = T::splat;
    let c = s(2.0) * zeta * omega;
    -gamma * s(ground_change) - load_now
        + pseudo_change
        + (s(4.0 / hh) + s(2.0) * c) * v
        + s(2.0) * a
}

/// Newmark's discrete energy identity over a mode's step from v0 to v1 that moved it by dq
/// (`[omega, zeta, gamma]` the mode's, `ground` the ground's acceleration at both ends summed):
/// the ground's work, half the sum of its forces times the displacement, and the damping's,
/// h/4 c (v0 + v1)^2.
#[inline(always)]
pub(super) fn energy_terms<T: Lane>(
    dq: T,
    v0: T,
    v1: T,
    [omega, zeta, gamma]: [T; 3],
    hh: f64,
    ground: f64,
) -> (T, T) {
    let s = T::splat;
    let speed = v0 + v1;
    (
        s(0.5) * dq * (-gamma) * s(ground),
        s(0.25 * hh * 2.0) * zeta * omega * (speed * speed),
    )
}

/// A mode's velocity and acceleration at the end of a Newmark step of length hh that moved it
/// by dq from velocity v0 and acceleration a0, in incremental form.
#[inline(always)]
pub(super) fn newmark_end<T: Lane>(dq: T, v0: T, a0: T, hh: f64) -> (T, T) {
    let s = T::splat;
    let dv = s(2.0) * dq / s(hh) - s(2.0) * v0;
    let da = s(4.0) * (dq - s(hh) * v0) / s(hh * hh) - s(2.0) * a0;
    (v0 + dv, a0 + da)
}

#[cfg(test)]
mod tests {
    use super::super::{fixed_signed, fixed_values};
    use super::*;

    #[test]
    fn a_sum_in_lanes_has_the_same_bits_on_every_processor() {
        for n in 0..=130 {
            let (c, q, d) = (
                fixed_signed(n as u64, n),
                fixed_signed(7 + n as u64, n),
                fixed_signed(99, n),
            );
            assert_eq!(dot(&c, &q).to_bits(), dot_in::<F4>(&c, &q).to_bits());
            assert_eq!(
                dot_moved(&c, &q, &d).to_bits(),
                dot_moved_in::<F4>(&c, &q, &d).to_bits()
            );
            // Mode by mode: no sums across modes, so exactly the scalar operations.
            let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            let mut sums = q.clone();
            add_scaled(&mut sums, &c, 0.37);
            let by_hand: Vec<f64> = q.iter().zip(&c).map(|(s, r)| s + r * 0.37).collect();
            assert_eq!(bits(&sums), bits(&by_hand));
            let k_hat: Vec<f64> = c.iter().map(|c| 2.0 + c).collect();
            let (mut dq, mut load) = (vec![0.0; n], d.clone());
            with_forces(&mut dq, &mut load, &q, &k_hat, -1.0);
            let by_hand: Vec<f64> = (0..n).map(|k| q[k] + -d[k] / k_hat[k]).collect();
            assert_eq!(bits(&dq), bits(&by_hand));
            assert_eq!(
                bits(&load),
                bits(&d.iter().map(|f| -f + 0.0).collect::<Vec<_>>())
            );
            // One point's force: as a cleared sum with its load added, then the increments.
            let (mut one_dq, mut one_load) = (vec![0.0; n], vec![f64::NAN; n]);
            with_one_force(&mut one_dq, &mut one_load, &q, &k_hat, &c, -0.61, 1.0);
            let (mut two_dq, mut two_load) = (vec![0.0; n], vec![0.0; n]);
            add_scaled(&mut two_load, &c, -0.61);
            with_forces(&mut two_dq, &mut two_load, &q, &k_hat, 1.0);
            assert_eq!(bits(&one_dq), bits(&two_dq), "{n}");
            assert_eq!(bits(&one_load), bits(&two_load), "{n}");
            let (mut dq2, mut load2) = (vec![0.0; n], c.clone());
            with_forces(&mut dq2, &mut load2, &q, &k_hat, 1.0);
            let by_hand: Vec<f64> = (0..n).map(|k| q[k] + c[k] / k_hat[k]).collect();
            assert_eq!(bits(&dq2), bits(&by_hand));
            assert_eq!(
                bits(&load2),
                bits(&c.iter().map(|f| f + 0.0).collect::<Vec<_>>())
            );
            // A table of n rows over 7 modes: each row's four weighted sums, mode after mode.
            let modes = 7;
            let abs: Vec<f64> = fixed_values(40 + n as u64, modes * n);
            let m: [Vec<f64>; 4] = std::array::from_fn(|b| fixed_signed(50 + b as u64, modes));
            let by_hand: [Vec<f64>; 4] = std::array::from_fn(|b| {
                (0..n)
                    .map(|j| (0..modes).fold(0.0, |sum, k| sum + abs[k * n + j] * m[b][k]))
                    .collect()
            });
            let mut out: [Vec<f64>; 4] = std::array::from_fn(|_| vec![f64::NAN; n]);
            let [o0, o1, o2, o3] = &mut out;
            weigh_rows(&abs, n, [&m[0], &m[1], &m[2], &m[3]], [o0, o1, o2, o3]);
            let mut scalars: [Vec<f64>; 4] = std::array::from_fn(|_| vec![f64::NAN; n]);
            let [o0, o1, o2, o3] = &mut scalars;
            weigh_rows_in::<F4>(&abs, n, [&m[0], &m[1], &m[2], &m[3]], [o0, o1, o2, o3]);
            for b in 0..4 {
                assert_eq!(bits(&out[b]), bits(&by_hand[b]), "{n}");
                assert_eq!(bits(&scalars[b]), bits(&by_hand[b]), "{n}");
            }
            let both = dot2(&c, &q, &d);
            assert_eq!(
                [both.0.to_bits(), both.1.to_bits()],
                [dot(&c, &q).to_bits(), dot(&c, &d).to_bits()]
            );
            let both = dot2_in::<F4>(&c, &q, &d);
            assert_eq!(
                [both.0.to_bits(), both.1.to_bits()],
                [dot(&c, &q).to_bits(), dot(&c, &d).to_bits()]
            );
            let a = fixed_signed(3 + n as u64, n);
            let apart = [dot(&c, &q), dot(&c, &d), dot(&c, &a)].map(f64::to_bits);
            assert_eq!(dot3(&c, &q, &d, &a).map(f64::to_bits), apart, "{n}");
            assert_eq!(
                dot3_in::<F4>(&c, &q, &d, &a).map(f64::to_bits),
                apart,
                "{n}"
            );
            // Mode k in lane k mod 4, the lanes joined pairwise: written out term by term (the
            // sixteen-mode blocks change no term's place).
            let mut lane = [0.0f64; 4];
            let mut plain = [0.0f64; 4];
            for k in 0..n {
                lane[k % 4] += c[k] * (q[k] + d[k]);
                plain[k % 4] += c[k] * q[k];
            }
            let by_hand = (lane[0] + lane[2]) + (lane[1] + lane[3]);
            assert_eq!(dot_moved(&c, &q, &d).to_bits(), by_hand.to_bits(), "{n}");
            let by_hand = (plain[0] + plain[2]) + (plain[1] + plain[3]);
            assert_eq!(dot(&c, &q).to_bits(), by_hand.to_bits(), "{n}");
        }
    }

    /// A commit of q, v and a (in that order).
    type CommitFn<'a> = dyn Fn(&mut [f64], &mut [f64], &mut [f64]) -> Committed + 'a;
    /// Exact states q, v and accelerations (in that order).
    type StatesFn<'a> = dyn Fn(&mut [f64], &mut [f64], &mut [f64]) + 'a;

    #[test]
    fn a_commit_in_lanes_has_the_same_bits_on_every_processor() {
        for n in [0, 1, 3, 4, 5, 16, 17, 103] {
            let [q0, v0, dq, a0, omega, zeta, gamma] =
                std::array::from_fn(|k| fixed_signed(11 * k as u64 + n as u64, n));
            let e = Ends {
                q0: &q0,
                v0: &v0,
                dq: &dq,
                coefficients: [&omega, &zeta, &gamma],
                hh: 1.3e-3,
                ground: 0.7,
            };
            let run = |lanes: &CommitFn| {
                let (mut q, mut v, mut a) = (vec![0.0; n], vec![0.0; n], a0.clone());
                let c = lanes(&mut q, &mut v, &mut a);
                let sums = [
                    c.input, c.damping, c.moved[0], c.moved[1], c.speed[0], c.speed[1],
                ];
                [q, v, a, sums.to_vec()].map(|x| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
            };
            let found = run(&|q, v, a| commit(&e, q, v, a));
            assert_eq!(found, run(&|q, v, a| commit_in::<F4>(&e, q, v, a)));
            // Mode by mode, mode k's terms in lane k mod 4, the lanes joined pairwise.
            let by_hand = run(&|q, v, a| {
                let mut lane = [[0.0f64; 4]; 6];
                // Newmark's ends and energy terms written out as the scalar step wrote them
                // before the lanes (not through the functions under test).
                let hh = e.hh;
                for k in 0..n {
                    let v1 = v0[k] + (2.0 * dq[k] / hh - 2.0 * v0[k]);
                    let a1 = a[k] + (4.0 * (dq[k] - hh * v0[k]) / (hh * hh) - 2.0 * a[k]);
                    let input = 0.5 * dq[k] * (-gamma[k]) * e.ground;
                    let damping = 0.25 * hh * 2.0 * zeta[k] * omega[k] * (v0[k] + v1).powi(2);
                    let terms = [
                        input,
                        damping,
                        dq[k].abs(),
                        dq[k] * dq[k],
                        v1.abs(),
                        v1 * v1,
                    ];
                    for (lane, term) in lane.iter_mut().zip(terms) {
                        lane[k % 4] += term;
                    }
                    (q[k], v[k], a[k]) = (q0[k] + dq[k], v1, a1);
                }
                let join = |l: [f64; 4]| (l[0] + l[2]) + (l[1] + l[3]);
                Committed {
                    input: join(lane[0]),
                    damping: join(lane[1]),
                    moved: [join(lane[2]), join(lane[3]).sqrt()],
                    speed: [join(lane[4]), join(lane[5]).sqrt()],
                }
            });
            assert_eq!(found, by_hand, "{n} modes");
            // Newmark's increments: no sums across modes, so each mode's scalar formula.
            let k_hat: Vec<f64> = omega.iter().map(|w| 2.0 + w).collect();
            let inc = Increment {
                coefficients: [&omega, &zeta, &gamma],
                v: &v0,
                a: &a0,
                k_hat: &k_hat,
                load_now: &q0,
                hh: 1.3e-3,
                ground_change: -0.2,
            };
            let steps = |f: &dyn Fn(&mut [f64])| {
                let mut out = vec![0.0; n];
                f(&mut out);
                out.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
            };
            let found = steps(&|out| increment(&inc, out));
            assert_eq!(found, steps(&|out| increment_in::<F4>(&inc, out)));
            let by_hand = steps(&|out| {
                // Newmark's incremental load written out, not through `increment_load`.
                let hh = 1.3e-3;
                for k in 0..n {
                    let c = 2.0 * zeta[k] * omega[k];
                    let load =
                        -gamma[k] * -0.2 - q0[k] + 0.0 + (4.0 / hh + 2.0 * c) * v0[k] + 2.0 * a0[k];
                    out[k] = load / k_hat[k];
                }
            });
            assert_eq!(found, by_hand, "{n} modes");
        }
    }

    #[test]
    fn a_free_stretchs_exact_states_have_the_same_bits_on_every_processor() {
        for n in [0, 1, 5, 100] {
            let w = fixed_signed(3 + n as u64, 14 * n);
            let maps: Vec<Propagator> = w
                .chunks_exact(14)
                .map(|c| Propagator {
                    q: [c[0], c[1], c[2], c[3]],
                    v: [c[4], c[5], c[6], c[7]],
                })
                .collect();
            let y0: Vec<[f64; 4]> = w
                .chunks_exact(14)
                .map(|c| [c[8], c[9], c[10], c[11]])
                .collect();
            let (damping, stiffness): (Vec<f64>, Vec<f64>) =
                w.chunks_exact(14).map(|c| (c[12], 1e4 * c[13])).unzip();
            let e = Exact {
                maps: &maps,
                y0: &y0,
                damping: &damping,
                stiffness: &stiffness,
                s: 0.37,
            };
            let states = |f: &StatesFn| {
                let (mut q, mut v, mut a) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
                f(&mut q, &mut v, &mut a);
                [q, v, a].map(|x| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
            };
            let found = states(&|q, v, a| exact_states(&e, q, v, a));
            // Mode by mode: the map's pairs, then the acceleration's terms left to right.
            let by_hand = states(&|q, v, a| {
                for k in 0..n {
                    let (p, y) = (&maps[k], &y0[k]);
                    q[k] = (p.q[0] * y[0] + p.q[1] * y[1]) + (p.q[2] * y[2] + p.q[3] * y[3]);
                    v[k] = (p.v[0] * y[0] + p.v[1] * y[1]) + (p.v[2] * y[2] + p.v[3] * y[3]);
                    a[k] = y[2] + y[3] * 0.37 - damping[k] * v[k] - stiffness[k] * q[k];
                }
            });
            assert_eq!(found, by_hand, "{n} modes");
        }
    }

    #[test]
    fn a_slabs_tabulated_ringing_in_lanes_has_the_same_bits_as_point_by_point() {
        use crate::model::ringing::stencil;
        let w = [0.1, -0.35, 0.8, 0.45];
        let far_w = [0.3, 0.2, -0.1, 0.6];
        for n in [0, 1, 3, 4, 9, 130] {
            let src = fixed_signed(5 + n as u64, n + 3);
            let other = fixed_signed(6 + n as u64, n + 3);
            let a = fixed_signed(7, n);
            let bits = |x: &[f64]| x.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            let mut todo = vec![0.0; n];
            ringing_block(&mut todo, &a, &src, &w, 0.93, 1.07);
            let by_hand: Vec<f64> = (0..n)
                .map(|k| (a[k] + 0.93 * stencil(&w, &src[k..k + 4])) * 1.07)
                .collect();
            assert_eq!(bits(&todo), bits(&by_hand), "{n} points");
            let e = Elastic {
                near: (&src, &w),
                far: (&other, &far_w),
                newest: &a,
                b: &src,
                constants: [0.9, 0.4, 2.5, 0.7, 1e-3],
            };
            let mut out = vec![0.0; n];
            elastic_rows(&e, &mut out);
            let by_hand: Vec<f64> = (0..n)
                .map(|k| {
                    let near_far =
                        0.9 * stencil(&w, &src[k..k + 4]) + 0.4 * stencil(&far_w, &other[k..k + 4]);
                    2.5 * (near_far + 0.7 * a[k]) - 1e-3 * src[k]
                })
                .collect();
            assert_eq!(bits(&out), bits(&by_hand), "{n} points");
        }
    }
}
