//! The two-bone IK's common case for up to `N` chains at once ([`ChainLanes`]), one
//! array per component, so that the compiler runs the same arithmetic for several chains
//! in one vector instruction.
//!
//! The common case is a chain that [`TwoBoneIk::solve_with_axes`] solves without any of its
//! fallbacks: finite globals and target, a target away from bone A, a usable pole, bones of
//! non-zero length, full weight, and both local axes usable (its one-step frame rotation).
//! For such a chain the result here is `solve_with_axes`'s, bit for bit, on x86-64 builds
//! without fused multiply-add ([`LANES_MATCH_GLAM`]): every value is computed with the
//! same operations in the same order (glam's SSE2 code's, on separate components, as in
//! [`super::super::parts`]), and the cases of the law of cosines and of reading a
//! rotation off a frame are chosen per chain as selects rather than branches. Chains that
//! need a fallback are left to `solve_with_axes` (their answer is `None`), so the two paths
//! together give the one-chain answer for every input.
//!
//! Each step is one operation on all `N` chains ([`L`]: a loop over `N` numbers, which the
//! compiler turns into vector instructions), rather than one loop running the whole solve
//! chain by chain: a loop body that large is not vectorised. The products of several
//! components (rotations, cross products, a frame's columns) are the exception: each is one
//! loop over the chains whose body is the whole product ([`per_chain`]), which stays
//! vectorised across the chains however much code is optimised around it.

use super::{
    BoneAxes, IkReport, LEN_EPS, PARALLEL_EPS, Pole, REACH_TOLERANCE, TwoBoneIk, stretch_scale,
};
use crate::kernels::parts::mul_parts;
use core::ops::{Add, BitAnd, Div, Mul, Neg, Sub};
use strider_core::Transform;

/// Whether this build's glam computes with the operations and order the lanes copy (its
/// SSE2 code, without fused multiply-add), so that the lanes' answers are the one-chain
/// solve's bit for bit. Elsewhere (other processors' SIMD code, or `fma`, which rounds a
/// product and a sum once) a caller that needs the one-chain answers solves each chain
/// alone.
pub const LANES_MATCH_GLAM: bool = cfg!(all(target_arch = "x86_64", not(target_feature = "fma")));

/// One chain's input to [`ChainLanes::set`]: its settings and the current globals of bone A,
/// bone B and the effector, and the target (all rig space, cm).
#[derive(Clone, Copy, Debug)]
pub struct ChainInput {
    /// The solve's settings. Its `primary_axis` and `secondary_axis` are not read: the
    /// lanes take the axes shared by all chains ([`BoneAxes`], given to
    /// [`ChainLanes::solve`]).
    pub ik: TwoBoneIk,
    /// The current global transforms of bone A, bone B and the effector.
    pub globals: [Transform; 3],
    /// The effector's goal.
    pub target: Transform,
    /// The current global transform of bone A's parent, `None` when A has none: for the
    /// chain's new local transforms ([`ChainSolution::locals`]).
    pub parent: Option<Transform>,
}

/// A solved chain: the new global transforms of bone A, bone B and the effector, their
/// local transforms when the chain is a limb, and the solve's report.
#[derive(Clone, Copy, Debug)]
pub struct ChainSolution {
    /// Bone A, bone B and the effector, rig space.
    pub globals: [Transform; 3],
    /// Bone A's new global relative to its parent's (the global itself for a bone
    /// without a parent), B's relative to A's and the effector's relative to B's, as
    /// [`strider_core::Pose::set_chain_globals`] computes them for a chain whose B is A's
    /// child and whose effector is B's: the two to be written with
    /// [`strider_core::Pose::set_chain_with_locals`]. `None` when the parent's global is
    /// not finite (then `set_chain_globals`).
    pub locals: Option<[Transform; 3]>,
    /// As [`TwoBoneIk::solve_with_axes`] reports it.
    pub report: IkReport,
}

/// One number per chain: `N` of them, each operation a loop over all `N`. Written here
/// because the standard library's portable SIMD is not stable, and a SIMD crate would fix
/// the vector width when this crate is built rather than in the caller compiled for wider
/// registers (see `ChainLanes::solve`).
#[derive(Clone, Copy, Debug)]
struct L<T, const N: usize>([T; N]);

/// `N` three-component vectors, one [`L`] per component.
type V<const N: usize> = [L<f32, N>; 3];
/// `N` rotations `[x, y, z, w]`, one [`L`] per component.
type Q<const N: usize> = [L<f32, N>; 4];
/// `N` true-or-false values as masks: every bit set for true, none for false (a bool
/// per chain is compared, combined and chosen by one lane at a time).
type B<const N: usize> = L<u32, N>;

/// `c` as a mask.
#[inline(always)]
fn mask(c: bool) -> u32 {
    u32::from(c).wrapping_neg()
}

/// A number chosen by a mask, bit for bit: the bits of `a` where `m` is set, else `b`'s.
trait Choose: Copy + Default {
    fn choose(m: u32, a: Self, b: Self) -> Self;
}

impl Choose for f32 {
    #[inline(always)]
    fn choose(m: u32, a: Self, b: Self) -> Self {
        f32::from_bits((a.to_bits() & m) | (b.to_bits() & !m))
    }
}

impl Choose for f64 {
    #[inline(always)]
    fn choose(m: u32, a: Self, b: Self) -> Self {
        let m = u64::from(m) | (u64::from(m) << 32);
        f64::from_bits((a.to_bits() & m) | (b.to_bits() & !m))
    }
}

impl Choose for u32 {
    #[inline(always)]
    fn choose(m: u32, a: Self, b: Self) -> Self {
        (a & m) | (b & !m)
    }
}

impl<T: Copy, const N: usize> L<T, N> {
    #[inline(always)]
    fn splat(x: T) -> Self {
        Self([x; N])
    }

    /// `f` of each number.
    #[inline(always)]
    fn map<U: Copy + Default>(self, f: impl Fn(T) -> U) -> L<U, N> {
        let mut out = [U::default(); N];
        // The inputs indexed: a loop over the arrays' own iterators (by value) is not
        // vectorised.
        for (m, o) in out.iter_mut().enumerate() {
            *o = f(self.0[m]);
        }
        L(out)
    }

    /// `f` of each pair of numbers.
    #[inline(always)]
    fn zip<U: Copy + Default>(self, other: Self, f: impl Fn(T, T) -> U) -> L<U, N> {
        let mut out = [U::default(); N];
        for (m, o) in out.iter_mut().enumerate() {
            *o = f(self.0[m], other.0[m]);
        }
        L(out)
    }
}

impl<const N: usize> B<N> {
    /// The masks of `N` bools.
    #[inline(always)]
    fn of(c: [bool; N]) -> Self {
        L(c).map(mask)
    }

    /// Whether each mask is set.
    #[inline(always)]
    fn bools(self) -> [bool; N] {
        self.map(|m| m != 0).0
    }

    /// `a` where true, else `b` (a select per number, not a branch).
    #[inline(always)]
    fn pick<T: Choose>(self, a: L<T, N>, b: L<T, N>) -> L<T, N> {
        let mut out = [T::default(); N];
        for (m, o) in out.iter_mut().enumerate() {
            *o = T::choose(self.0[m], a.0[m], b.0[m]);
        }
        L(out)
    }

    /// [`B::pick`] of each component.
    #[inline(always)]
    fn pick_all<T: Choose, const C: usize>(
        self,
        mut a: [L<T, N>; C],
        b: [L<T, N>; C],
    ) -> [L<T, N>; C] {
        // A plain loop: `array::from_fn` and `array::map` leave calls behind here.
        for c in 0..C {
            a[c] = self.pick(a[c], b[c]);
        }
        a
    }
}

impl<const N: usize> BitAnd for B<N> {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, other: Self) -> Self {
        self.zip(other, |a, b| a & b)
    }
}

/// The arithmetic of [`L`]: each operation on each number, as Rust does it on one.
macro_rules! arithmetic {
    ($($t:ty),*) => {$(
        impl<const N: usize> Add for L<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self { self.zip(o, |a, b| a + b) }
        }
        impl<const N: usize> Sub for L<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self { self.zip(o, |a, b| a - b) }
        }
        impl<const N: usize> Mul for L<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn mul(self, o: Self) -> Self { self.zip(o, |a, b| a * b) }
        }
        impl<const N: usize> Div for L<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn div(self, o: Self) -> Self { self.zip(o, |a, b| a / b) }
        }
        impl<const N: usize> Neg for L<$t, N> {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self { self.map(|a| -a) }
        }
        impl<const N: usize> L<$t, N> {
            #[inline(always)]
            fn sqrt(self) -> Self { self.map(<$t>::sqrt) }
            #[inline(always)]
            fn max(self, o: Self) -> Self { self.zip(o, <$t>::max) }
            #[inline(always)]
            fn min(self, o: Self) -> Self { self.zip(o, <$t>::min) }
            #[inline(always)]
            fn le(self, o: Self) -> B<N> { self.zip(o, |a, b| mask(a <= b)) }
        }
    )*};
}
arithmetic!(f32, f64);

/// What the solve asks of single-precision numbers beyond [`arithmetic!`].
impl<const N: usize> L<f32, N> {
    #[inline(always)]
    fn abs(self) -> Self {
        self.map(f32::abs)
    }
    #[inline(always)]
    fn finite(self) -> B<N> {
        self.map(|a| mask(a.is_finite()))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> B<N> {
        self.zip(o, |a, b| mask(a < b))
    }
    #[inline(always)]
    fn gt(self, o: Self) -> B<N> {
        self.zip(o, |a, b| mask(a > b))
    }
    #[inline(always)]
    fn ge(self, o: Self) -> B<N> {
        self.zip(o, |a, b| mask(a >= b))
    }
    #[inline(always)]
    fn eq(self, o: Self) -> B<N> {
        self.zip(o, |a, b| mask(a == b))
    }
}

/// Chain `m`'s vector or rotation out of `v`.
#[inline(always)]
fn get<const N: usize, const C: usize>(v: &[L<f32, N>; C], m: usize) -> [f32; C] {
    let mut x = [0.0; C];
    for (x, col) in x.iter_mut().zip(v) {
        *x = col.0[m];
    }
    x
}

/// Writes chain `m`'s vector or rotation `x` into `v`.
#[inline(always)]
fn put<const N: usize, const C: usize>(v: &mut [L<f32, N>; C], m: usize, x: [f32; C]) {
    for (col, x) in v.iter_mut().zip(x) {
        col.0[m] = x;
    }
}

/// `f` of each chain's components of `a` and `b`, computed chain by chain in one loop
/// whose body is all of `f`. The lanes' products of several components go through here
/// rather than through whole-lane operations: with the crate graph optimised as one (fat
/// LTO), the compiler turns those sixteen-lane operations partly into single floats and
/// four-float vectors across the components, while a loop over the chains stays eight
/// chains at a time.
#[inline(always)]
fn per_chain<const N: usize, const A: usize, const B: usize, const C: usize>(
    a: &[L<f32, N>; A],
    b: &[L<f32, N>; B],
    f: impl Fn([f32; A], [f32; B]) -> [f32; C],
) -> [L<f32, N>; C] {
    let mut out = [L([0.0; N]); C];
    for m in 0..N {
        put(&mut out, m, f(get(a, m), get(b, m)));
    }
    out
}

/// The rotations `a · b`, as [`mul_parts`] of each chain's.
#[inline(always)]
fn quat_mul<const N: usize>(a: &Q<N>, b: &Q<N>) -> Q<N> {
    per_chain(a, b, mul_parts::<f32>)
}

/// `a · b` summed as glam's three-component dot product: `(x + y) + z`.
#[inline(always)]
fn dot<const N: usize>(a: V<N>, b: V<N>) -> L<f32, N> {
    (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2]
}

/// `a × b`, each component one product minus another, as glam's.
#[inline(always)]
fn cross<const N: usize>(a: V<N>, b: V<N>) -> V<N> {
    per_chain(&a, &b, |a, b| {
        [
            a[1] * b[2] - b[1] * a[2],
            a[2] * b[0] - b[2] * a[0],
            a[0] * b[1] - b[0] * a[1],
        ]
    })
}

#[inline(always)]
fn sub<const N: usize>(a: V<N>, b: V<N>) -> V<N> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
fn add<const N: usize>(a: V<N>, b: V<N>) -> V<N> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

#[inline(always)]
fn scale<const N: usize>(a: V<N>, k: L<f32, N>) -> V<N> {
    [a[0] * k, a[1] * k, a[2] * k]
}

/// `v`'s length as glam's `Vec3A::length`.
#[inline(always)]
fn length<const N: usize>(v: V<N>) -> L<f32, N> {
    dot(v, v).sqrt()
}

/// The part of `v` perpendicular to the unit `dir`, normalised, as `perpendicular` in the
/// one-chain solve, and whether it exists (where not, the vector is garbage).
#[inline(always)]
fn perpendicular<const N: usize>(v: V<N>, dir: V<N>) -> (V<N>, B<N>) {
    let len_sq = dot(v, v);
    let usable = len_sq.gt(L::splat(0.0)) & len_sq.finite();
    let p = sub(v, scale(dir, dot(v, dir)));
    let apart = dot(p, p).gt(L::splat(PARALLEL_EPS * PARALLEL_EPS) * len_sq);
    let q = sub(p, scale(dir, dot(p, dir)));
    // `try_normalize`: the reciprocal of the length, usable when finite and positive.
    let rcp = L::splat(1.0) / length(q);
    let normal = rcp.finite() & rcp.gt(L::splat(0.0));
    (scale(q, rcp), usable & apart & normal)
}

/// `v`'s direction as `direction` in the one-chain solve takes it when `v`'s squared
/// length is finite, and whether that is the case with a length above [`LEN_EPS`].
#[inline(always)]
fn direction<const N: usize>(v: V<N>) -> (V<N>, B<N>) {
    let len_sq = dot(v, v);
    let len = len_sq.sqrt();
    (
        [v[0] / len, v[1] / len, v[2] / len],
        len_sq.finite() & len_sq.gt(L::splat(LEN_EPS * LEN_EPS)),
    )
}

/// Whether `v`'s squared length is finite and above `LEN_EPS²` (`has_direction`; where the
/// squared length overflows, the one-chain solve looks further and the lanes give up).
#[inline(always)]
fn has_direction<const N: usize>(v: V<N>) -> B<N> {
    let len_sq = dot(v, v);
    len_sq.finite() & len_sq.gt(L::splat(LEN_EPS * LEN_EPS))
}

/// `q · r` summed as glam's four-component dot product: `(x + z) + (y + w)`.
#[inline(always)]
fn dot4<const N: usize>(q: Q<N>, r: Q<N>) -> L<f32, N> {
    (q[0] * r[0] + q[2] * r[2]) + (q[1] * r[1] + q[3] * r[3])
}

/// `q` normalised as `unit_q` (`(x² + z²) + (y² + w²)`, one division per component), or the
/// identity where its length is zero or not finite.
#[inline(always)]
fn unit<const N: usize>(q: Q<N>) -> Q<N> {
    let len = dot4(q, q).sqrt();
    let ok = len.gt(L::splat(0.0)) & len.finite();
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    ok.pick_all(
        [q[0] / len, q[1] / len, q[2] / len, q[3] / len],
        [zero, zero, zero, one],
    )
}

/// The rotation read off the orthonormal frame with columns `x`, `y`, `z`, as glam's
/// `Quat::from_rotation_axes`: its four cases computed as one, by selects.
#[inline(always)]
fn from_axes<const N: usize>(x: V<N>, y: V<N>, z: V<N>) -> Q<N> {
    let ([m00, m01, m02], [m10, m11, m12], [m20, m21, m22]) = (x, y, z);
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    let lower = m22.le(zero);
    let (dif10, sum10) = (m11 - m00, m11 + m00);
    let (omm22, opm22) = (one - m22, one + m22);
    // Within each half, the first case or the second.
    let first = lower.pick(dif10.le(zero), sum10.le(zero));
    let four_sq = lower.pick(
        first.pick(omm22 - dif10, omm22 + dif10),
        first.pick(opm22 - sum10, opm22 + sum10),
    );
    let inv = L::splat(0.5) / four_sq.sqrt();
    let (s01, d01) = (m01 + m10, m01 - m10);
    let (s02, d20) = (m02 + m20, m20 - m02);
    let (s12, d12) = (m12 + m21, m12 - m21);
    let parts = lower.pick_all(
        first.pick_all([four_sq, s01, s02, d12], [s01, four_sq, s12, d20]),
        first.pick_all([s02, s12, four_sq, d01], [d12, d20, d01, four_sq]),
    );
    [
        parts[0] * inv,
        parts[1] * inv,
        parts[2] * inv,
        parts[3] * inv,
    ]
}

/// The frame with columns `frame` times the vector `l`, as glam's `Mat3A * Vec3A`: one
/// column of `solved * local_inverse` in `bone_rotation`.
#[inline(always)]
fn frame_times<const N: usize>(frame: &[V<N>; 3], [lx, ly, lz]: [f32; 3]) -> V<N> {
    let [x, y, z] = frame;
    let xy = per_chain(x, y, |x, y| {
        [
            x[0] * lx + y[0] * ly,
            x[1] * lx + y[1] * ly,
            x[2] * lx + y[2] * ly,
        ]
    });
    per_chain(&xy, z, |xy, z| {
        [xy[0] + z[0] * lz, xy[1] + z[1] * lz, xy[2] + z[2] * lz]
    })
}

/// `v` rotated by the unit rotation `q`, in the order of operations of
/// [`crate::kernels::parts::rotate_parts`] (glam's `Quat * Vec3A`).
#[inline(always)]
fn rotate<const N: usize>(q: Q<N>, v: V<N>) -> V<N> {
    let [x, y, z, w] = q;
    let two = L::splat(2.0);
    let k = w * w - ((x * x + y * y) + z * z);
    let d = ((v[0] * x + v[1] * y) + v[2] * z) * two;
    let w2 = w * two;
    let c = cross([x, y, z], v);
    [
        (v[0] * k + x * d) + c[0] * w2,
        (v[1] * k + y * d) + c[1] * w2,
        (v[2] * k + z * d) + c[2] * w2,
    ]
}

/// The transform `(translation, rotation, scale)` relative to `parent`, as
/// `Transform::relative_to`: rotation `p.r⁻¹ · r` normalised (divided by its length, as
/// glam's `Quat::normalize`), scale `s / p.s` and translation `(p.r⁻¹ · (t − p.t)) / p.s`,
/// with 0 on an axis where the parent's scale is 0.
#[inline(always)]
fn relative_to<const N: usize>(
    (t, r, s): (V<N>, Q<N>, V<N>),
    (pt, pr, ps): (V<N>, Q<N>, V<N>),
) -> (V<N>, Q<N>, V<N>) {
    let (zero, one) = (L::splat(0.0), L::splat(1.0));
    let inverse = |c: L<f32, N>| c.eq(zero).pick(zero, one / c);
    let inv_s = [inverse(ps[0]), inverse(ps[1]), inverse(ps[2])];
    let inv_r = [-pr[0], -pr[1], -pr[2], pr[3]];
    let moved = rotate(inv_r, sub(t, pt));
    let q = quat_mul(&inv_r, &r);
    let len = dot4(q, q).sqrt();
    (
        [
            inv_s[0] * moved[0],
            inv_s[1] * moved[1],
            inv_s[2] * moved[2],
        ],
        [q[0] / len, q[1] / len, q[2] / len, q[3] / len],
        [inv_s[0] * s[0], inv_s[1] * s[1], inv_s[2] * s[2]],
    )
}

/// `Σ (x − x)` over the components of `v`: 0 exactly when every one is finite.
#[inline(always)]
fn spread<const N: usize, const C: usize>(v: &[L<f32, N>; C]) -> L<f32, N> {
    let mut sum = L::splat(0.0);
    for &c in v {
        // `c − c` on purpose: 0 for a finite number, NaN otherwise.
        #[allow(clippy::eq_op)]
        let zero = c - c;
        sum = sum + zero;
    }
    sum
}

/// A bone's new rotation as `bone_rotation` takes it with both local axes usable, and
/// whether it took that path (a bone of non-zero length, before and after, whose wanted
/// secondary axis exists).
#[inline(always)]
fn bone_rotation<const N: usize>(
    current: Q<N>,
    local_inverse: &[[f32; 3]; 3],
    old_offset: V<N>,
    new_offset: V<N>,
    normal: V<N>,
) -> (Q<N>, B<N>) {
    let (dir, along) = direction(new_offset);
    let (want, wanted) = perpendicular(cross(normal, dir), dir);
    let solved = [dir, want, cross(dir, want)];
    let q = from_axes(
        frame_times(&solved, local_inverse[0]),
        frame_times(&solved, local_inverse[1]),
        frame_times(&solved, local_inverse[2]),
    );
    let flip = dot4(q, current).lt(L::splat(0.0));
    let ok = along & has_direction(old_offset) & wanted;
    let minus = L::splat(-1.0);
    (
        flip.pick_all([q[0] * minus, q[1] * minus, q[2] * minus, q[3] * minus], q),
        ok,
    )
}

/// Up to `N` chains' inputs and answers, one array per component: set each chain
/// ([`ChainLanes::set`]), solve them all ([`ChainLanes::solve`]), read each answer
/// ([`ChainLanes::solution`]).
#[derive(Clone, Debug)]
pub struct ChainLanes<const N: usize> {
    /// Bone A's, bone B's and the effector's current positions, and the target's.
    root: V<N>,
    mid: V<N>,
    end: V<N>,
    goal: V<N>,
    /// The pole as a direction (a location minus bone A's position).
    pole: V<N>,
    /// Bone A's, bone B's and the effector's current rotations, and the target's.
    rot_a: Q<N>,
    rot_b: Q<N>,
    rot_e: Q<N>,
    goal_rot: Q<N>,
    /// Bone A's, bone B's and the effector's scales, kept as they are.
    scale_a: V<N>,
    scale_b: V<N>,
    scale_e: V<N>,
    /// Bone A's parent's global transform (the identity for none), whether there is one,
    /// and whether it is finite.
    parent_t: V<N>,
    parent_r: Q<N>,
    parent_s: V<N>,
    has_parent: [bool; N],
    parent_finite: [bool; N],
    /// Whether the chain's scales and the target's are finite.
    finite_scales: [bool; N],
    weight: [f32; N],
    stretch: [Option<(f32, f32)>; N],
    own_rotation: [bool; N],
    /// The chains [`ChainLanes::set`] gave.
    live: [bool; N],
    /// The answers: positions of bone B and the effector, the three rotations, the
    /// distance left to the target, and whether the chain was solved here.
    new_mid: V<N>,
    new_end: V<N>,
    qa: Q<N>,
    qb: Q<N>,
    qe: Q<N>,
    /// The chain's new locals: translations, rotations and scales of bone A, bone B and
    /// the effector.
    local_t: [V<N>; 3],
    local_r: [Q<N>; 3],
    local_s: [V<N>; 3],
    distance: [f32; N],
    solved: [bool; N],
}

impl<const N: usize> Default for ChainLanes<N> {
    fn default() -> Self {
        Self {
            root: [L([0.0; N]); 3],
            mid: [L([0.0; N]); 3],
            end: [L([0.0; N]); 3],
            goal: [L([0.0; N]); 3],
            pole: [L([0.0; N]); 3],
            rot_a: [L([0.0; N]); 4],
            rot_b: [L([0.0; N]); 4],
            rot_e: [L([0.0; N]); 4],
            goal_rot: [L([0.0; N]); 4],
            scale_a: [L([1.0; N]); 3],
            scale_b: [L([1.0; N]); 3],
            scale_e: [L([1.0; N]); 3],
            parent_t: [L([0.0; N]); 3],
            parent_r: [L([0.0; N]); 4],
            parent_s: [L([1.0; N]); 3],
            has_parent: [false; N],
            parent_finite: [false; N],
            finite_scales: [false; N],
            weight: [0.0; N],
            stretch: [None; N],
            own_rotation: [false; N],
            live: [false; N],
            new_mid: [L([0.0; N]); 3],
            new_end: [L([0.0; N]); 3],
            qa: [L([0.0; N]); 4],
            qb: [L([0.0; N]); 4],
            qe: [L([0.0; N]); 4],
            local_t: [[L([0.0; N]); 3]; 3],
            local_r: [[L([0.0; N]); 4]; 3],
            local_s: [[L([0.0; N]); 3]; 3],
            distance: [0.0; N],
            solved: [false; N],
        }
    }
}

impl<const N: usize> ChainLanes<N> {
    /// Unsets every chain, as [`Default`] leaves them, but keeps the numbers of the chains
    /// set before: lanes that [`ChainLanes::set`] does not give again are computed on and
    /// never read, so lanes used once more need no filling.
    #[inline]
    pub fn unset_all(&mut self) {
        self.live = [false; N];
        self.solved = [false; N];
    }

    /// Sets chain `m` (`< N`) to be solved by the next [`ChainLanes::solve`].
    #[inline(always)]
    pub fn set(&mut self, m: usize, x: &ChainInput) {
        let [ga, gb, ge] = x.globals;
        let root = ga.translation.to_array();
        put(&mut self.root, m, root);
        put(&mut self.mid, m, gb.translation.to_array());
        put(&mut self.end, m, ge.translation.to_array());
        put(&mut self.goal, m, x.target.translation.to_array());
        put(&mut self.rot_a, m, ga.rotation.to_array());
        put(&mut self.rot_b, m, gb.rotation.to_array());
        put(&mut self.rot_e, m, ge.rotation.to_array());
        put(&mut self.goal_rot, m, x.target.rotation.to_array());
        let (p, location) = match x.ik.pole {
            Pole::Direction(v) => (v.to_array(), false),
            Pole::Location(p) => (p.to_array(), true),
        };
        // `Pole::Location`: the pole is the vector from bone A.
        let from_root = [p[0] - root[0], p[1] - root[1], p[2] - root[2]];
        put(&mut self.pole, m, if location { from_root } else { p });
        put(&mut self.scale_a, m, ga.scale.to_array());
        put(&mut self.scale_b, m, gb.scale.to_array());
        put(&mut self.scale_e, m, ge.scale.to_array());
        let parent = x.parent.unwrap_or(Transform::IDENTITY);
        put(&mut self.parent_t, m, parent.translation.to_array());
        put(&mut self.parent_r, m, parent.rotation.to_array());
        put(&mut self.parent_s, m, parent.scale.to_array());
        self.has_parent[m] = x.parent.is_some();
        self.parent_finite[m] = parent.is_finite();
        self.finite_scales[m] = strider_core::all_finite([
            glam::Vec3A::from(ga.scale),
            glam::Vec3A::from(gb.scale),
            glam::Vec3A::from(ge.scale),
            glam::Vec3A::from(x.target.scale),
        ]);
        self.weight[m] = x.ik.weight;
        self.stretch[m] = x.ik.stretch;
        self.own_rotation[m] = x.ik.set_effector_rotation;
        self.live[m] = true;
    }

    /// Whether chains with the local axes `axes` can be solved on lanes at all: when both
    /// axes are usable (the one-chain solve's one-step frame rotation); otherwise
    /// [`ChainLanes::solve`] solves none.
    #[must_use]
    pub fn solves_with(axes: &BoneAxes) -> bool {
        axes.local_inverse.is_some()
    }

    /// Solves every chain set since the lanes were made or last unset
    /// ([`ChainLanes::unset_all`]) that
    /// [`TwoBoneIk::solve_with_axes`] would solve without a fallback (see the module docs),
    /// all with the local axes `axes`. None is solved when `axes` has no usable local
    /// frame. Always inlined, so that a caller compiled for wider vector registers runs it
    /// on them.
    #[inline(always)]
    pub fn solve(&mut self, axes: &BoneAxes) {
        let Some(local_inverse) = axes.local_inverse else {
            self.solved = [false; N];
            return;
        };
        let local_inverse = [
            local_inverse.x_axis.to_array(),
            local_inverse.y_axis.to_array(),
            local_inverse.z_axis.to_array(),
        ];
        let (r, b, e, g) = (self.root, self.mid, self.end, self.goal);
        let (l1, l2, wanted) = (length(sub(b, r)), length(sub(e, b)), length(sub(g, r)));
        let total = l1 + l2;
        // The stretch factor, whose cases are branches: one chain at a time, as the
        // one-chain solve computes it.
        let mut k = L::splat(1.0f32);
        for m in 0..N {
            let f = stretch_scale(self.stretch[m], wanted.0[m] / total.0[m]);
            k.0[m] = if (total.0[m] * f).is_finite() { f } else { 1.0 };
        }
        // Every position and rotation finite.
        let spread = ((spread(&r) + spread(&b)) + (spread(&e) + spread(&g)))
            + ((spread(&self.rot_a) + spread(&self.rot_b))
                + (spread(&self.rot_e) + spread(&self.goal_rot)));
        // Chain direction and bend side (the first candidate of each).
        let (dir, aimed) = direction(sub(g, r));
        let (side, sided) = perpendicular(self.pole, dir);
        // Law of cosines (`place_joints`).
        let long = total.gt(L::splat(LEN_EPS)) & total.finite();
        let (l1, l2) = (l1 * k, l2 * k);
        let d = wanted.max((l1 - l2).abs()).min(l1 + l2);
        let (l1d, l2d, dd) = (l1.map(f64::from), l2.map(f64::from), d.map(f64::from));
        let folded = l1.ge(l2).pick(l1d, -l1d);
        let general = (dd * dd + l1d * l1d - l2d * l2d) / (L::splat(2.0) * dd);
        let x = d.ge(l1 + l2).pick(
            l1d,
            dd.le(L::splat(1e-9))
                .pick(L::splat(0.0), d.le((l1 - l2).abs()).pick(folded, general)),
        );
        let x = x.max(-l1d).min(l1d);
        let h = (l1d * l1d - x * x).max(L::splat(0.0)).sqrt();
        let (x, h) = (x.map(|x| x as f32), h.map(|h| h as f32));
        let new_mid = add(add(r, scale(dir, x)), scale(side, h));
        let new_end = d.eq(wanted).pick_all(g, add(r, scale(dir, d)));
        // The report (`IkReport::measure`).
        let miss = length(sub(new_end, g));
        self.distance = miss.finite().pick(miss, L::splat(f32::INFINITY)).0;
        // The rotations.
        let normal = cross(dir, side);
        let (qa, a_ok) = bone_rotation(
            self.rot_a,
            &local_inverse,
            sub(b, r),
            sub(new_mid, r),
            normal,
        );
        let (qb, b_ok) = bone_rotation(
            self.rot_b,
            &local_inverse,
            sub(e, b),
            sub(new_end, new_mid),
            normal,
        );
        let rb = self.rot_b;
        let e_in_b = quat_mul(&[-rb[0], -rb[1], -rb[2], rb[3]], &self.rot_e);
        let own = B::of(self.own_rotation);
        self.qe = own.pick_all(unit(self.goal_rot), unit(quat_mul(&qb, &e_in_b)));
        self.new_mid = new_mid;
        self.new_end = new_end;
        self.qa = qa;
        self.qb = qb;
        // Less than full weight blends (NaN counts as 0): the one-chain solve does that.
        let full = L(self.weight).ge(L::splat(1.0));
        let finite = spread.eq(L::splat(0.0)) & B::of(self.finite_scales);
        let solved = B::of(self.live) & full & finite & aimed & sided & long & a_ok & b_ok;
        self.solved = solved.bools();
    }

    /// The new locals of the chains the last [`ChainLanes::solve`] solved (see
    /// [`ChainSolution::locals`]). Apart from `solve` so that each, compiled alone, keeps
    /// its operations on vector registers. Always inlined, as `solve`.
    #[inline(always)]
    pub fn relate(&mut self) {
        // As `Pose::set_chain_globals`: A's relative to its parent's global, B's to A's
        // new one, the effector's to B's.
        let (r, qa, sa) = (self.root, self.qa, self.scale_a);
        let (mid, qb, sb) = (self.new_mid, self.qb, self.scale_b);
        let (end, qe, se) = (self.new_end, self.qe, self.scale_e);
        let parent = (self.parent_t, self.parent_r, self.parent_s);
        let (ta, ra, a_s) = relative_to((r, qa, sa), parent);
        let has_parent = B::of(self.has_parent);
        self.local_t[0] = has_parent.pick_all(ta, r);
        self.local_r[0] = has_parent.pick_all(ra, qa);
        self.local_s[0] = has_parent.pick_all(a_s, sa);
        (self.local_t[1], self.local_r[1], self.local_s[1]) =
            relative_to((mid, qb, sb), (r, qa, sa));
        (self.local_t[2], self.local_r[2], self.local_s[2]) =
            relative_to((end, qe, se), (mid, qb, sb));
    }

    /// Chain `m`'s answer from the last [`ChainLanes::solve`] (and [`ChainLanes::relate`]
    /// for its locals): the globals and report
    /// [`TwoBoneIk::solve_with_axes`] gives, bit for bit; `None` when the lanes did not
    /// solve it (the caller then solves it with `solve_with_axes`).
    #[inline(always)]
    #[must_use]
    pub fn solution(&self, m: usize) -> Option<ChainSolution> {
        if !self.solved[m] {
            return None;
        }
        let quat = |q: &Q<N>| glam::Quat::from_array(get(q, m));
        let vec = |v: &V<N>| glam::Vec3::from_array(get(v, m));
        let local = |k: usize| {
            Transform::new(
                vec(&self.local_t[k]),
                quat(&self.local_r[k]),
                vec(&self.local_s[k]),
            )
        };
        Some(ChainSolution {
            globals: [
                Transform::new(vec(&self.root), quat(&self.qa), vec(&self.scale_a)),
                Transform::new(vec(&self.new_mid), quat(&self.qb), vec(&self.scale_b)),
                Transform::new(vec(&self.new_end), quat(&self.qe), vec(&self.scale_e)),
            ],
            locals: self.parent_finite[m].then(|| [local(0), local(1), local(2)]),
            report: IkReport {
                reached: self.distance[m] <= REACH_TOLERANCE,
                distance_to_target: self.distance[m],
            },
        })
    }
}
