//! A batch's scalar slots, interleaved by member ([`Lanes`]), and the plain scalar ops run
//! on all of a batch's members at once ([`run_wide`]).
//!
//! While a batch runs ([`crate::exec`]'s batch loop), slot `k` of member `m` of each scalar
//! type lives at item `k * BATCH + m` of that type's array here: the same slot of every
//! member side by side. Every handler reaches a member's slots through its lane (base
//! pointers `m` items on, stride [`BATCH`]), so the handlers that work member by member run
//! unchanged; and an op whose handler only computes scalar slots from scalar slots runs as
//! one loop over [`BATCH`] lanes, which the compiler turns into vector instructions, instead
//! of one handler run per member.

// Slot blocks are read and written through the batch's base pointers, like the executor's
// unchecked slot access (see `exec`): this module's only unsafe code.
#![allow(unsafe_code)]

use crate::array_lanes::ArrayLanes;
use crate::exec::{BATCH, Bases, Ctx};
use crate::slots::{ScalarLens, Slots};
use crate::transpose::{
    QuatColumns, Vec3Columns, quat_columns, quat_rows, rotation_columns, scale_columns,
    vec3_columns, vec3_rows,
};
use glam::{Quat, Vec3};
use std::cell::RefCell;
use strider_core::Transform;
use strider_nodes::kernels as k;
use strider_nodes::kernels::locomotion as loco;
use strider_nodes::kernels::parts;
use strider_nodes::kernels::two_bone_ik::LANES_MATCH_GLAM;
use strider_nodes::{Elem, Op, ValueType};

/// A batch's scalar slots, interleaved by member: slot `k` of member `m` is item
/// `k * BATCH + m` of its type's array.
#[derive(Default)]
pub(crate) struct Lanes {
    bools: Vec<bool>,
    ints: Vec<i32>,
    floats: Vec<f32>,
    vec3s: Vec<Vec3>,
    quats: Vec<Quat>,
    transforms: Vec<Transform>,
    /// Copies of the batch's array variables, side by side as the scalar slots are.
    pub(crate) arrays: ArrayLanes,
    /// The program (`Program::id`; 0: none) whose initial values every lane holds in the
    /// slots no instruction of it writes (each type's `written..lens`): the last batch
    /// loaded was of that program and took them from it. 0 after a batch that copied its
    /// members' own (one of them held other values there).
    unwritten_of: u64,
}

/// Which of a program's scalar slots a batch copies between its members and the lanes, per
/// type: in, slots `0..kept` and `written..lens`; back, `0..kept`.
///
/// Slot sharing ([`crate::sharing`]) numbers each type's slots as: those whose value may be
/// read before it is written in a run (graph variables, state kept from frame to frame)
/// and that an instruction writes, `0..kept`; then the shared slots of values that live
/// only within a run, `kept..written`, which every run writes before it reads them; then
/// the slots no instruction writes (constants, variables only the host sets),
/// `written..lens`: when every member holds the program's initial values there (the host
/// has set none of those variables), the lanes take them from `initial` and keep them for
/// the program's next batches. The shared slots' lanes start a batch with whatever an
/// earlier batch left there, which no run reads. With `kept` = `written` every written slot goes both
/// ways, so the members' own slots end as a run on them alone leaves them.
#[derive(Clone, Copy)]
pub(crate) struct Copies<'p> {
    /// One past each type's highest slot: every slot the program has.
    pub(crate) lens: &'p ScalarLens,
    /// Each type's slots `0..kept` are copied in and back.
    pub(crate) kept: &'p ScalarLens,
    /// Each type's slots from `written` on are copied in only (no instruction writes them).
    pub(crate) written: &'p ScalarLens,
    /// The program's `id` when every member holds `initial`'s values in the slots from
    /// `written` on; else 0, and each member's are copied.
    pub(crate) program: u64,
    /// The program's initial slots.
    pub(crate) initial: &'p Slots,
}

/// No slots at all: the initial values of [`Copies::all`], which reads none.
#[cfg(test)]
static NO_SLOTS: Slots = Slots {
    bools: Vec::new(),
    ints: Vec::new(),
    floats: Vec::new(),
    vec3s: Vec::new(),
    quats: Vec::new(),
    transforms: Vec::new(),
    bones: Vec::new(),
    names: Vec::new(),
    bool_arrays: Vec::new(),
    int_arrays: Vec::new(),
    float_arrays: Vec::new(),
    vec3_arrays: Vec::new(),
    quat_arrays: Vec::new(),
    transform_arrays: Vec::new(),
    bone_arrays: Vec::new(),
};

impl<'p> Copies<'p> {
    /// Every slot in, every slot back (`lens` = `kept` = `written`).
    #[cfg(test)]
    pub(crate) fn all(lens: &'p ScalarLens) -> Self {
        Self {
            lens,
            kept: lens,
            written: lens,
            program: 0,
            // Read only for a program's unwritten slots, of which there are none here.
            initial: &NO_SLOTS,
        }
    }
}

thread_local! {
    /// Each thread's lanes, reused by every batch it runs: they grow to the largest
    /// program's slots once and are not reallocated after that.
    pub(crate) static LANES: RefCell<Lanes> = RefCell::new(Lanes::default());
}

/// Runs `$m!(array, index in ScalarLens)` for each scalar slot type.
macro_rules! each_scalar_type {
    ($m:ident) => {
        $m!(bools, 0);
        $m!(ints, 1);
        $m!(floats, 2);
        $m!(vec3s, 3);
        $m!(quats, 4);
        $m!(transforms, 5);
    };
}

impl Lanes {
    /// Copies each scalar type's slots `0..copies.kept` and `copies.written..copies.lens`
    /// of every member in (growing the lanes to `lens` slots of [`BATCH`] members where
    /// they are shorter). `members` has at most [`BATCH`] members, each covering `lens`.
    /// Member by member: each member's array is read in order into its lane (every
    /// [`BATCH`]th item). With `copies.program`, whose initial values every member holds
    /// in `copies.written..copies.lens`, those come from `copies.initial` into every lane
    /// instead, unless the lanes hold them already. Starts the batch's run of array copies
    /// ([`ArrayLanes::begin`]) with none.
    #[inline(always)]
    pub(crate) fn load(&mut self, copies: Copies<'_>, members: &[Ctx<'_>]) {
        assert!(members.len() <= BATCH, "a batch has at most BATCH members");
        let (program, held) = (copies.program, self.unwritten_of);
        // Until the lanes are loaded, they hold no program's values.
        self.unwritten_of = 0;
        self.reserve(copies.lens);
        self.arrays.begin(copies.initial);
        macro_rules! load {
            ($a:ident, $t:expr) => {{
                let len = copies.lens.0[$t];
                let kept = copies.kept.0[$t].min(len);
                let rest = copies.written.0[$t].clamp(kept, len);
                let lanes = self.$a[..len * BATCH].as_mut_ptr();
                for (m, cx) in members.iter().enumerate() {
                    let from = &cx.slots.$a[..len];
                    // Two plain loops: one over a chained range costs more per slot.
                    for (k, &x) in from[..kept].iter().enumerate() {
                        // SAFETY: `k < len` and `m < BATCH`, and the lanes hold
                        // `len * BATCH` items (grown above, and sliced to that).
                        unsafe { *lanes.add(k * BATCH + m) = x };
                    }
                    if program == 0 {
                        for (k, &x) in from[rest..].iter().enumerate() {
                            // SAFETY: as above, `rest + k < len`.
                            unsafe { *lanes.add((rest + k) * BATCH + m) = x };
                        }
                    }
                }
                if program != 0 && program != held {
                    let blocks = self.$a[rest * BATCH..len * BATCH].chunks_exact_mut(BATCH);
                    for (block, &x) in blocks.zip(&copies.initial.$a[rest..len]) {
                        block.fill(x);
                    }
                }
            }};
        }
        each_scalar_type!(load);
        self.unwritten_of = program;
    }

    /// Grows each scalar type's lanes to `lens` slots of [`BATCH`] members where they are
    /// shorter (the items added hold default values; the others keep theirs).
    #[inline(always)]
    pub(crate) fn reserve(&mut self, lens: &ScalarLens) {
        macro_rules! grow {
            ($a:ident, $t:expr) => {{
                let len = lens.0[$t] * BATCH;
                if self.$a.len() < len {
                    self.$a.resize(len, Default::default());
                }
            }};
        }
        each_scalar_type!(grow);
    }

    /// Copies each scalar type's slots `0..copies.kept` back to every member, member by
    /// member.
    #[inline(always)]
    pub(crate) fn store(&self, copies: Copies<'_>, members: &mut [Ctx<'_>]) {
        assert!(members.len() <= BATCH, "a batch has at most BATCH members");
        macro_rules! store {
            ($a:ident, $t:expr) => {{
                let len = copies.kept.0[$t];
                let lanes = self.$a[..len * BATCH].as_ptr();
                for (m, cx) in members.iter_mut().enumerate() {
                    for (k, to) in cx.slots.$a[..len].iter_mut().enumerate() {
                        // SAFETY: `k < len` and `m < BATCH`, and the lanes hold
                        // `len * BATCH` items (the slice above checked it).
                        *to = unsafe { *lanes.add(k * BATCH + m) };
                    }
                }
            }};
        }
        each_scalar_type!(store);
    }

    /// Base pointers of member 0's lane (member `m`'s: [`Bases::lane`]). Valid while the
    /// lanes are not resized: for a whole batch run.
    pub(crate) fn bases(&mut self) -> Bases {
        Bases {
            bools: self.bools.as_mut_ptr(),
            ints: self.ints.as_mut_ptr(),
            floats: self.floats.as_mut_ptr(),
            vec3s: self.vec3s.as_mut_ptr(),
            quats: self.quats.as_mut_ptr(),
            transforms: self.transforms.as_mut_ptr(),
        }
    }
}

/// The block of [`BATCH`] lanes of slot `slot` of the array at `base`.
#[inline(always)]
pub(crate) fn block<T>(base: *mut T, slot: u32) -> *mut [T; BATCH] {
    base.wrapping_add(slot as usize * BATCH).cast()
}

/// Item `m` of block `out` becomes item `m` of `x` where `c[m]`, else of `y`, lane by
/// lane (each lane read before it is written, so `out` may be `x` or `y`); the whole
/// block of one of them when every lane chooses it.
///
/// # Safety
/// The three blocks must be valid for reads and writes of [`BATCH`] items.
#[inline(always)]
unsafe fn select_items<T: Copy>(
    c: [bool; BATCH],
    x: *mut [T; BATCH],
    y: *mut [T; BATCH],
    out: *mut [T; BATCH],
) {
    match bools_agree(c, BATCH) {
        // SAFETY: the caller's contract; `copy` allows the blocks to be one.
        Some(false) => return unsafe { std::ptr::copy(y, out, 1) },
        // SAFETY: as above.
        Some(true) => return unsafe { std::ptr::copy(x, out, 1) },
        None => {}
    }
    let (x, y, out) = (x.cast::<T>(), y.cast::<T>(), out.cast::<T>());
    for (m, &c) in c.iter().enumerate() {
        let from = if c { x } else { y };
        // SAFETY: `m < BATCH`, by the caller's contract.
        unsafe { *out.add(m) = *from.add(m) };
    }
}

/// A block's components as one array per component (`[x; 16], [y; 16], …`), so that
/// math over them runs as vectorised loops across the lanes (see
/// [`strider_nodes::kernels::parts`]).
#[inline(always)]
fn columns<T, const C: usize>(
    block: &[T; BATCH],
    parts: impl Fn(&T) -> [f32; C],
) -> [[f32; BATCH]; C] {
    let mut cols = [[0.0; BATCH]; C];
    for (m, item) in block.iter().enumerate() {
        for (col, x) in cols.iter_mut().zip(parts(item)) {
            col[m] = x;
        }
    }
    cols
}

/// Lane `m` of component arrays `cols`.
#[inline(always)]
fn lane<const C: usize>(cols: &[[f32; BATCH]; C], m: usize) -> [f32; C] {
    std::array::from_fn(|c| cols[c][m])
}

/// Sets lane `m` of component arrays `cols`.
#[inline(always)]
fn set_lane<const C: usize>(cols: &mut [[f32; BATCH]; C], m: usize, x: [f32; C]) {
    for (col, x) in cols.iter_mut().zip(x) {
        col[m] = x;
    }
}

/// A block of transforms as component arrays: translation, rotation, scale. The
/// translations are gathered a float at a time: four floats from a translation on would
/// take in the padding after it, which holds no value.
#[inline(always)]
fn transform_columns(block: &[Transform; BATCH]) -> (Vec3Columns, QuatColumns, Vec3Columns) {
    (
        columns(block, |t| t.translation.to_array()),
        rotation_columns(block),
        scale_columns(block),
    )
}

/// A block of transforms as component arrays: translation, rotation, scale.
type TransformColumns = (Vec3Columns, QuatColumns, Vec3Columns);

/// The block `out` becomes the transforms of component arrays `(t, r, s)`: translation,
/// rotation, scale.
///
/// # Safety
/// `out` must be a block of the lanes.
#[inline(always)]
unsafe fn put_transform_rows(out: *mut [Transform; BATCH], (t, r, s): &TransformColumns) {
    let (mut translations, mut rotations, mut scales) = (
        [Vec3::ZERO; BATCH],
        [Quat::IDENTITY; BATCH],
        [Vec3::ZERO; BATCH],
    );
    vec3_rows(t, &mut translations);
    quat_rows(r, &mut rotations);
    vec3_rows(s, &mut scales);
    // SAFETY: the caller's contract.
    unsafe { put_transforms(out, &translations, &rotations, &scales) };
}

// The copies of 16 bytes rely on this layout: 4 bytes of padding after the translation
// (the rotation is 16-byte aligned) and after the scale.
const _: () = assert!(
    std::mem::offset_of!(Transform, rotation) == 16
        && std::mem::offset_of!(Transform, scale) == 32
        && size_of::<Transform>() == 48
);

/// Lane `m` of the block `out` becomes the transform of translation `t[m]`, rotation
/// `r[m]` and scale `s[m]`. The translations and scales of every lane but the last are
/// copied as 16 bytes, the vector and the first component of the next one, which land in
/// the transform's padding: one load and one store where a 12-byte vector takes two of
/// each. Only bytes move, so every bit arrives.
///
/// # Safety
/// `out` must be a block of the lanes, outside `t`, `r` and `s`.
#[inline(always)]
unsafe fn put_transforms(
    out: *mut [Transform; BATCH],
    t: &[Vec3; BATCH],
    r: &[Quat; BATCH],
    s: &[Vec3; BATCH],
) {
    let out = out.cast::<Transform>();
    // Pointers into the whole arrays (not through one item's reference), so that 16 bytes
    // from an item that is not the last may be read.
    let (t_at, s_at) = (t.as_ptr(), s.as_ptr());
    for (m, &rotation) in r[..BATCH - 1].iter().enumerate() {
        // SAFETY: the caller's contract; `m + 1 < BATCH`, so 16 bytes from item `m` of `t`
        // and `s` are readable, and 4 bytes of padding follow a transform's translation
        // and scale.
        unsafe {
            let to = out.add(m);
            copy_vec3_wide(t_at.add(m), &raw mut (*to).translation);
            (*to).rotation = rotation;
            copy_vec3_wide(s_at.add(m), &raw mut (*to).scale);
        }
    }
    let last = BATCH - 1;
    // SAFETY: the caller's contract.
    unsafe { *out.add(last) = Transform::new(t[last], r[last], s[last]) };
}

/// The exponential lerps' weights `exp_alpha(speed, dt)` of the first `n` lanes (0 for the
/// others), computed once for each run of members with the same speed and time step, bit
/// for bit (so the same weight), as a crowd's members usually have: once for a whole batch
/// alike.
#[inline(always)]
fn weights(speed: &[f32; BATCH], dts: &[f32; BATCH], n: usize) -> [f32; BATCH] {
    if n == BATCH && Uniform::uniform(speed) && Uniform::uniform(dts) {
        // The whole batch alike: one weight.
        return [loco::exp_alpha(speed[0], dts[0]); BATCH];
    }
    let mut alphas = [0.0f32; BATCH];
    let mut last: Option<(u32, u32, f32)> = None;
    for (m, alpha) in alphas.iter_mut().enumerate().take(n) {
        let (s, d) = (speed[m].to_bits(), dts[m].to_bits());
        *alpha = match last {
            Some((ls, ld, w)) if ls == s && ld == d => w,
            _ => {
                let w = loco::exp_alpha(speed[m], dts[m]);
                last = Some((s, d, w));
                w
            }
        };
    }
    alphas
}

/// `a[m] · b[m]` for every lane (`Transform`'s product: `b` placed in `a`'s frame), on
/// component arrays, in glam's order of operations: translation `a.t + a.r · (a.s ⊙ b.t)`,
/// rotation `a.r · b.r` normalised, scale `a.s ⊙ b.s`.
#[inline(always)]
fn transform_products(a: &[Transform; BATCH], b: &[Transform; BATCH]) -> TransformColumns {
    let (at, ar, a_scale) = transform_columns(a);
    let (bt, br, b_scale) = transform_columns(b);
    let (mut t, mut r, mut s) = ([[0.0; BATCH]; 3], [[0.0; BATCH]; 4], [[0.0; BATCH]; 3]);
    for m in 0..BATCH {
        let scaled = std::array::from_fn(|c| a_scale[c][m] * bt[c][m]);
        let turned = parts::rotate_parts(lane(&ar, m), scaled);
        set_lane(&mut t, m, std::array::from_fn(|c| at[c][m] + turned[c]));
        let q = parts::mul_parts(lane(&ar, m), lane(&br, m));
        set_lane(&mut r, m, parts::normalize_parts(q));
        set_lane(
            &mut s,
            m,
            std::array::from_fn(|c| a_scale[c][m] * b_scale[c][m]),
        );
    }
    (t, r, s)
}

/// `1 / x`, or 0 where `x` is ±0 (`Transform`'s inverse scale, per component).
#[inline(always)]
fn reciprocal_or_zero(x: f32) -> f32 {
    if x == 0.0 { 0.0 } else { 1.0 / x }
}

/// `a[m]` relative to `parent[m]` for every lane ([`Transform::relative_to`]), on component
/// arrays, in its order of operations: with `p.r⁻¹` the conjugate and `1 / p.s` zero on a
/// zero axis, translation `(1 / p.s) ⊙ (p.r⁻¹ · (a.t − p.t))`, rotation `p.r⁻¹ · a.r`
/// normalised, scale `(1 / p.s) ⊙ a.s`. Without `a` ([`Transform::inverse`]): translation
/// `(1 / p.s) ⊙ (p.r⁻¹ · −p.t)`, rotation `p.r⁻¹`, scale `1 / p.s`.
#[inline(always)]
fn transforms_relative(
    a: Option<&[Transform; BATCH]>,
    parent: &[Transform; BATCH],
) -> TransformColumns {
    let (pt, pr, p_scale) = transform_columns(parent);
    let own = a.map(transform_columns);
    let (mut t, mut r, mut s) = ([[0.0; BATCH]; 3], [[0.0; BATCH]; 4], [[0.0; BATCH]; 3]);
    for m in 0..BATCH {
        let inv_scale: [f32; 3] = std::array::from_fn(|c| reciprocal_or_zero(p_scale[c][m]));
        let [x, y, z, w] = lane(&pr, m);
        let inv_rotation = [-x, -y, -z, w];
        let offset = match &own {
            Some((at, _, _)) => std::array::from_fn(|c| at[c][m] - pt[c][m]),
            None => std::array::from_fn(|c| -pt[c][m]),
        };
        let turned = parts::rotate_parts(inv_rotation, offset);
        set_lane(&mut t, m, std::array::from_fn(|c| inv_scale[c] * turned[c]));
        match &own {
            Some((_, ar, a_scale)) => {
                let q = parts::mul_parts(inv_rotation, lane(ar, m));
                set_lane(&mut r, m, parts::normalize_parts(q));
                set_lane(
                    &mut s,
                    m,
                    std::array::from_fn(|c| inv_scale[c] * a_scale[c][m]),
                );
            }
            None => {
                set_lane(&mut r, m, inv_rotation);
                set_lane(&mut s, m, inv_scale);
            }
        }
    }
    (t, r, s)
}

/// Bit-for-bit equality of lane values (`-0.0` differs from `0.0`; a NaN equals only the
/// same NaN): two members with equal inputs in this sense get equal results from a kernel.
pub(crate) trait SameBits {
    /// Whether `self` and `other` have the same bits (every component's).
    fn same_bits(&self, other: &Self) -> bool;
}

impl SameBits for f32 {
    #[inline(always)]
    fn same_bits(&self, other: &Self) -> bool {
        self.to_bits() == other.to_bits()
    }
}

impl SameBits for Transform {
    #[inline(always)]
    fn same_bits(&self, other: &Self) -> bool {
        self.bit_eq(other)
    }
}

impl SameBits for bool {
    #[inline(always)]
    fn same_bits(&self, other: &Self) -> bool {
        self == other
    }
}

impl SameBits for i32 {
    #[inline(always)]
    fn same_bits(&self, other: &Self) -> bool {
        self == other
    }
}

/// Blocks whose lanes can be checked all alike at once ([`Uniform::uniform`]).
pub(crate) trait Uniform {
    /// Whether every lane of `block` holds lane 0's bits.
    fn uniform(block: &[Self; BATCH]) -> bool
    where
        Self: Sized;
}

/// Numbers, vectors and rotations are 32-bit words with no padding, and a bool is a byte:
/// a block is uniform when each word equals the word one item before it, which compares
/// the whole block a vector register at a time (no branch per lane).
macro_rules! uniform_words {
    ($($t:ty => $per:literal * $w:ty),+) => {$(
        // Exactly its words, no padding: a change of layout fails the build.
        const _: () = assert!(size_of::<$t>() == $per * size_of::<$w>());
        impl Uniform for $t {
            #[inline(always)]
            fn uniform(block: &[Self; BATCH]) -> bool {
                const PER: usize = $per;
                // SAFETY: the block's bytes are initialised words of `$w` (the items are
                // made of them, without padding), aligned as the items are.
                let words: &[$w; BATCH * PER] = unsafe { &*block.as_ptr().cast() };
                words[PER..]
                    .iter()
                    .zip(&words[..BATCH * PER - PER])
                    .fold(true, |same, (a, b)| same & (a == b))
            }
        }
    )+};
}
uniform_words!(f32 => 1 * u32, i32 => 1 * u32, Vec3 => 3 * u32, Quat => 4 * u32, bool => 1 * u8);

impl Uniform for Transform {
    /// Field by field: a transform has padding, which is not compared.
    #[inline(always)]
    fn uniform(block: &[Self; BATCH]) -> bool {
        block[1..]
            .iter()
            .fold(true, |same, t| same & t.same_bits(&block[0]))
    }
}

/// Vectors and rotations: every component's bits.
macro_rules! same_components {
    ($($t:ty),+) => {$(
        impl SameBits for $t {
            #[inline(always)]
            fn same_bits(&self, other: &Self) -> bool {
                self.to_array().map(f32::to_bits) == other.to_array().map(f32::to_bits)
            }
        }
    )+};
}
same_components!(Vec3, Quat);

/// Whether two blocks share no byte (blocks of different arrays never do).
fn disjoint<T, U>(a: *mut [T; BATCH], b: *mut [U; BATCH]) -> bool {
    let (a0, b0) = (a as usize, b as usize);
    a0 + size_of::<[T; BATCH]>() <= b0 || b0 + size_of::<[U; BATCH]>() <= a0
}

/// Whether the first `n` lanes of bool slot `slot` all hold `true` (`Some(true)`), all
/// hold `false` (`Some(false)`) or differ (`None`).
///
/// # Safety
/// `slot` must be a bool slot of the program the lanes at `lane0` are loaded for.
#[inline(always)]
pub(crate) unsafe fn agree(lane0: Bases, slot: u32, n: usize) -> Option<bool> {
    // SAFETY: in the lanes by the caller's contract.
    bools_agree(unsafe { *block(lane0.bools, slot) }, n)
}

/// Whether the first `n` of `held` are all `true` (`Some(true)`), all `false`
/// (`Some(false)`) or differ (`None`).
#[inline(always)]
fn bools_agree(held: [bool; BATCH], n: usize) -> Option<bool> {
    // A bool is one byte, 0 or 1: the block is tested as one 128-bit word, its first `n`
    // bytes kept.
    let word = u128::from_le_bytes(held.map(u8::from));
    let kept = u128::MAX
        .checked_shr(8 * (BATCH - n.min(BATCH)) as u32)
        .unwrap_or(0);
    match word & kept {
        0 => Some(false),
        w if w == 0x0101_0101_0101_0101_0101_0101_0101_0101 & kept => Some(true),
        _ => None,
    }
}

/// `BreakTransform` (operands `o`: transform; translation, rotation, scale) on every lane
/// of the batch whose member 0's lane is `lane0`: each part written for all lanes before
/// the next, in the handler's order (the last write wins where two parts share a slot).
///
/// # Safety
/// As [`run_wide`], with `o` a `BreakTransform`'s operands.
#[inline(always)]
pub(crate) unsafe fn break_transforms(o: &[u32], lane0: Bases) {
    // SAFETY: as in `run_wide`'s `lanes!`; the parts are of other types than the
    // transform.
    unsafe {
        let t = block(lane0.transforms, o[0]);
        put_vec3s(block(lane0.vec3s, o[1]), |m| &raw const (*t)[m].translation);
        for (r, x) in (*block(lane0.quats, o[2])).iter_mut().zip(&*t) {
            *r = x.rotation;
        }
        put_vec3s(block(lane0.vec3s, o[3]), |m| &raw const (*t)[m].scale);
    }
}

/// The vector at `from` copied to `to` as 16 bytes: the vector and the 4 bytes after it, one
/// load and one store. Only bytes move (padding may be among them), so every bit arrives.
///
/// # Safety
/// 16 bytes from `from` must be readable and 16 bytes from `to` writable (through pointers
/// that may reach them), and the two must not overlap; the 4 bytes after `to`'s vector
/// must be padding or be written again before anything reads them.
#[inline(always)]
unsafe fn copy_vec3_wide(from: *const Vec3, to: *mut Vec3) {
    // SAFETY: the caller's contract.
    unsafe { std::ptr::copy_nonoverlapping(from.cast::<u8>(), to.cast::<u8>(), 16) }
}

/// Lane `m` of the block `out` becomes the vector at `from(m)`, lane by lane in order.
/// Every lane but the last is copied as 16 bytes, the vector and the 4 bytes after it,
/// which land on the next lane's first component before that lane is written: one load
/// and one store where a 12-byte vector takes two of each. Only bytes move (a byte copy
/// may carry a transform's padding), so every bit arrives.
///
/// # Safety
/// `out` must be a block of the lanes or a local one; each `from(m)` must point at a
/// vector with 4 readable bytes after it (a transform's translation or scale: its padding
/// follows), outside `out`, and be derived from a pointer to the whole block of
/// transforms (not from a reference to one transform or field, whose access ends at its
/// own bytes).
#[inline(always)]
unsafe fn put_vec3s(out: *mut [Vec3; BATCH], from: impl Fn(usize) -> *const Vec3) {
    let out = out.cast::<Vec3>();
    for m in 0..BATCH - 1 {
        // SAFETY: the caller's contract; the 4 bytes written past lane `m` are lane
        // `m + 1`'s, written next.
        unsafe { copy_vec3_wide(from(m), out.add(m)) };
    }
    // SAFETY: as above; the last lane as 12 bytes, so nothing past the block is written.
    unsafe { *out.add(BATCH - 1) = *from(BATCH - 1) };
}

/// Runs `op` (operands `o`) on every lane of the batch whose member 0's lane is `lane0`,
/// when it is one of the ops whose handler computes scalar slots from scalar slots only,
/// and returns true; returns false, doing nothing, for every other op.
///
/// Each lane gets exactly what the op's handler in [`crate::exec`] computes for one
/// member: the same expression applied lane by lane, or for the ops on vectors,
/// rotations and transforms whose math mixes a value's components, the same operations
/// in the same order on component arrays (`parts`; the transform ops only where that is
/// glam's order, [`LANES_MATCH_GLAM`]). So results are bit-identical to running the
/// handler member by member — but for the bits of a NaN: when both operands of
/// an operation are NaN, which one's sign and payload the result carries is left open (by
/// Rust, and by the processor's vector and scalar instructions alike), and the vectorised
/// loop may pick the other one. A NaN stays a NaN. Lanes past the batch's members hold
/// stale values of earlier batches, which are computed on and never read.
///
/// `n` is the number of the batch's members, `dts` their time steps (s), member `m`'s at
/// `dts[m]`.
///
/// # Safety
/// `op` and `o` must be an instruction of a program built by
/// [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) (with its operand window), and
/// `lane0` the bases of [`Lanes`] loaded for that program's slots.
#[inline(always)]
pub(crate) unsafe fn run_wide(
    op: Op,
    o: &[u32],
    lane0: Bases,
    n: usize,
    dts: &[f32; BATCH],
) -> bool {
    // `out[k] = expression of inputs` on every lane: each input is slot operand `k` of
    // array `a`, read as a block before anything is written (an output may be an input),
    // and the result written into the output's block lane by lane.
    // Ops that call a kernel per lane (`n; ...`) compute the batch's `n` members' lanes
    // only; with `; dt` the expression also reads each member's time step.
    macro_rules! lanes {
        ($out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),+| $e:expr) => {{
            // SAFETY: the operand is a slot of this type (the op's layout), so its block
            // lies in the lanes (loaded for the program's slots).
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)+
            // SAFETY: as above; the inputs are copies, so this is the only reference.
            let out = unsafe { &mut *block(lane0.$out, o[$ko]) };
            for (m, r) in out.iter_mut().enumerate() {
                $(let $x = $x[m];)+
                *r = $e;
            }
        }};
        // Inputs after `; ref` are of other types than the output, so they cannot share its
        // block: they are read where they are, not copied. The first `$lanes` lanes.
        (@ref $lanes:expr; $out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),* ; ref $($y:ident: $b:ident[$kb:expr]),+| $e:expr) => {{
            // SAFETY: as above.
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)*
            $(
                debug_assert!(disjoint(block(lane0.$b, o[$kb]), block(lane0.$out, o[$ko])));
                // SAFETY: as above; in another array than the output's.
                let $y = unsafe { &*block(lane0.$b, o[$kb]) };
            )+
            // SAFETY: as above; no input refers to this array.
            let out = unsafe { &mut *block(lane0.$out, o[$ko]) };
            for (m, r) in out.iter_mut().enumerate().take($lanes) {
                $(let $x = $x[m];)*
                $(let $y = $y[m];)+
                *r = $e;
            }
        }};
        ($out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),* ; ref $($y:ident: $b:ident[$kb:expr]),+| $e:expr) => {
            lanes!(@ref BATCH; $out[$ko] = |$($x: $a[$k]),* ; ref $($y: $b[$kb]),+| $e)
        };
        (n; $out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),* ; ref $($y:ident: $b:ident[$kb:expr]),+| $e:expr) => {
            lanes!(@ref n; $out[$ko] = |$($x: $a[$k]),* ; ref $($y: $b[$kb]),+| $e)
        };
        (n; $out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),+ $(; $dt:ident)?| $e:expr) => {{
            // SAFETY: as above.
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)+
            // SAFETY: as above.
            let mut result = unsafe { *block(lane0.$out, o[$ko]) };
            for (m, r) in result.iter_mut().enumerate().take(n) {
                $(let $x = $x[m];)+
                $(let $dt = dts[m];)?
                *r = $e;
            }
            // SAFETY: as above.
            unsafe { *block(lane0.$out, o[$ko]) = result };
        }};
        // For costly kernels: a member whose inputs equal the previous member's, bit for
        // bit, takes its result instead of calling the kernel again (the kernels are pure,
        // and a crowd's characters often feed them the same values: shared tunables,
        // constant axes, feet at rest).
        (n, shared; $out:ident[$ko:expr] = |; ref $($y:ident: $b:ident[$kb:expr]),+| $e:expr) => {{
            $(
                debug_assert!(disjoint(block(lane0.$b, o[$kb]), block(lane0.$out, o[$ko])));
                // SAFETY: as above; in another array than the output's.
                let $y = unsafe { &*block(lane0.$b, o[$kb]) };
            )+
            // SAFETY: as above; no input refers to this array.
            let out = unsafe { &mut *block(lane0.$out, o[$ko]) };
            if n == BATCH $(&& Uniform::uniform($y))+ {
                // Every member's inputs are member 0's: so is every result.
                let r = {
                    $(let $y = $y[0];)+
                    $e
                };
                out.fill(r);
            } else {
                for m in 0..n {
                    out[m] = if m > 0 $(&& $y[m].same_bits(&$y[m - 1]))+ {
                        out[m - 1]
                    } else {
                        $(let $y = $y[m];)+
                        $e
                    };
                }
            }
        }};
        (n, shared; $out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),+ $(; $dt:ident)?| $e:expr) => {{
            // SAFETY: as above.
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)+
            // SAFETY: as above.
            let mut result = unsafe { *block(lane0.$out, o[$ko]) };
            if n == BATCH
                $(&& Uniform::uniform(&$x))+
                $(&& { stringify!($dt); Uniform::uniform(dts) })?
            {
                // Every member's inputs are member 0's: so is every result.
                let r = {
                    $(let $x = $x[0];)+
                    $(let $dt = dts[0];)?
                    $e
                };
                result = [r; BATCH];
            } else {
                for m in 0..n {
                    if m > 0
                        $(&& $x[m].same_bits(&$x[m - 1]))+
                        $(&& { stringify!($dt); dts[m].same_bits(&dts[m - 1]) })?
                    {
                        result[m] = result[m - 1];
                        continue;
                    }
                    $(let $x = $x[m];)+
                    $(let $dt = dts[m];)?
                    result[m] = $e;
                }
            }
            // SAFETY: as above.
            unsafe { *block(lane0.$out, o[$ko]) = result };
        }};
        // `n, shared` for kernels with several results, `(value => output slot)` each, in
        // the kernel's order. The outputs are distinct slots in a program (they may share
        // one in the op test, where the last write wins, as in the handler), so they are
        // written through pointers.
        (n, shared; ($($r:ident => $out:ident[$ko:expr]),+) = |$($x:ident: $a:ident[$k:expr]),+ $(; $dt:ident)?| $e:expr) => {{
            // SAFETY: as above.
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)+
            if n == BATCH
                $(&& Uniform::uniform(&$x))+
                $(&& { stringify!($dt); Uniform::uniform(dts) })?
            {
                // Every member's inputs are member 0's: so are all results. Each output
                // is filled in turn (where two share a slot, the last, as lane by lane).
                let ($($r,)+) = {
                    $(let $x = $x[0];)+
                    $(let $dt = dts[0];)?
                    $e
                };
                // SAFETY: as above.
                $(unsafe { *block(lane0.$out, o[$ko]) = [$r; BATCH] };)+
            } else {
                for m in 0..n {
                    if m > 0
                        $(&& $x[m].same_bits(&$x[m - 1]))+
                        $(&& { stringify!($dt); dts[m].same_bits(&dts[m - 1]) })?
                    {
                        // SAFETY: as above; `m < n <= BATCH`.
                        $(unsafe {
                            let out = block(lane0.$out, o[$ko]);
                            (*out)[m] = (*out)[m - 1];
                        })+
                        continue;
                    }
                    $(let $x = $x[m];)+
                    $(let $dt = dts[m];)?
                    let ($($r,)+) = $e;
                    // SAFETY: as above.
                    $(unsafe { (*block(lane0.$out, o[$ko]))[m] = $r };)+
                }
            }
        }};
        // The same as `n` for large outputs (transforms): written in place, lane by lane,
        // rather than through a copy of the whole block (which pays off for small values
        // only).
        (n, in place; $out:ident[$ko:expr] = |$($x:ident: $a:ident[$k:expr]),+| $e:expr) => {{
            // SAFETY: as above.
            $(let $x = unsafe { *block(lane0.$a, o[$k]) };)+
            // SAFETY: as above; the inputs are copies, so this is the only reference.
            let out = unsafe { &mut *block(lane0.$out, o[$ko]) };
            for (m, r) in out.iter_mut().enumerate().take(n) {
                $(let $x = $x[m];)+
                *r = $e;
            }
        }};
    }
    // The exponential lerps (operands: current, target, speed, result), whose weight
    // `exp_alpha(speed, dt)` is computed once for each run of members with the same speed
    // and dt (bit for bit, so the same weight), as a crowd's members usually have. The
    // weights come first, member by member (`weights`); then the lerp itself, as one loop
    // over the first `$lanes` lanes: a float lerp over every lane vectorises (lanes past
    // the members get weight 0 and are never read), a slerp runs for the members only.
    macro_rules! by_weight {
        ($a:ident, $apply:path, $lanes:expr) => {{
            // SAFETY: as in `lanes!`.
            let (current, target, speed) = unsafe {
                (
                    *block(lane0.$a, o[0]),
                    *block(lane0.$a, o[1]),
                    &*block(lane0.floats, o[2]),
                )
            };
            let alphas = weights(speed, dts, n);
            // SAFETY: as above; the lerped values are copies, so this is the only reference.
            let out = unsafe { &mut *block(lane0.$a, o[3]) };
            for (m, r) in out.iter_mut().enumerate().take($lanes) {
                *r = $apply(current[m], target[m], alphas[m]);
            }
        }};
    }
    macro_rules! arith {
        (AddF, $b:expr) => { lanes!(floats[$b + 2] = |a: floats[$b], b: floats[$b + 1]| a + b) };
        (SubF, $b:expr) => { lanes!(floats[$b + 2] = |a: floats[$b], b: floats[$b + 1]| a - b) };
        (MulF, $b:expr) => { lanes!(floats[$b + 2] = |a: floats[$b], b: floats[$b + 1]| a * b) };
        (DivF, $b:expr) => { lanes!(floats[$b + 2] = |a: floats[$b], b: floats[$b + 1]| k::div_f(a, b)) };
        (AddV, $b:expr) => { lanes!(vec3s[$b + 2] = |a: vec3s[$b], b: vec3s[$b + 1]| a + b) };
        (SubV, $b:expr) => { lanes!(vec3s[$b + 2] = |a: vec3s[$b], b: vec3s[$b + 1]| a - b) };
        (ScaleV, $b:expr) => { lanes!(vec3s[$b + 2] = |a: vec3s[$b], b: floats[$b + 1]| a * b) };
    }
    // The Select of a type: operand 0 the condition, 1 and 2 the choices, 3 the result.
    // Small values as a vectorised loop (ints and floats through a mask made of the
    // condition, bit for bit the chosen value, which the compiler does several lanes at a
    // time: 4.4 instead of 10 machine instructions per character with AVX2, 7 instead of
    // 9.5–10 without); vectors, rotations and transforms lane by lane
    // through the blocks' pointers (a lane is read before it is written, so the result
    // may share a choice's block), without copying whole blocks of them.
    macro_rules! select {
        (bools) => { lanes!(bools[3] = |c: bools[0], x: bools[1], y: bools[2]| if c { x } else { y }) };
        (ints) => { lanes!(ints[3] = |x: ints[1], y: ints[2], c: bools[0]| {
            let mask = i32::from(c).wrapping_neg();
            (x & mask) | (y & !mask)
        }) };
        (floats) => { lanes!(floats[3] = |x: floats[1], y: floats[2], c: bools[0]| {
            let mask = u32::from(c).wrapping_neg();
            f32::from_bits((x.to_bits() & mask) | (y.to_bits() & !mask))
        }) };
        ($a:ident) => {{
            // SAFETY: as in `lanes!`.
            unsafe {
                select_items(
                    *block(lane0.bools, o[0]),
                    block(lane0.$a, o[1]),
                    block(lane0.$a, o[2]),
                    block(lane0.$a, o[3]),
                )
            }
        }};
    }
    // The Copy of a type: the block as it is (the same block when they are one slot).
    macro_rules! copy {
        ($a:ident) => {
            // SAFETY: as in `lanes!`; `copy` allows the two blocks to be one.
            unsafe { std::ptr::copy(block(lane0.$a, o[0]), block(lane0.$a, o[1]), 1) }
        };
    }
    match op {
        Op::AddF => arith!(AddF, 0),
        Op::SubF => arith!(SubF, 0),
        Op::MulF => arith!(MulF, 0),
        Op::DivF => arith!(DivF, 0),
        Op::MinF => lanes!(floats[2] = |a: floats[0], b: floats[1]| a.min(b)),
        Op::MaxF => lanes!(floats[2] = |a: floats[0], b: floats[1]| a.max(b)),
        Op::AbsF => lanes!(floats[1] = |a: floats[0]| a.abs()),
        Op::NegF => lanes!(floats[1] = |a: floats[0]| -a),
        Op::ClampF => {
            lanes!(floats[3] = |a: floats[0], lo: floats[1], hi: floats[2]| k::clamp_f(a, lo, hi))
        }
        Op::SqrtF => lanes!(floats[1] = |a: floats[0]| k::sqrt(a)),
        Op::LerpF => {
            lanes!(floats[3] = |a: floats[0], b: floats[1], t: floats[2]| a + (b - a) * t)
        }
        Op::RemapF => lanes!(floats[6] = |x: floats[0], i0: floats[1], i1: floats[2],
            o0: floats[3], o1: floats[4], c: bools[5]| k::remap(x, i0, i1, o0, o1, c)),
        Op::SmoothStepF => lanes!(floats[3] = |x: floats[0], lo: floats[1], hi: floats[2]|
            k::smooth_step(x, lo, hi)),
        Op::IntToFloat | Op::ToFloat => lanes!(floats[1] = |a: ints[0]| a as f32),
        Op::AddI => lanes!(ints[2] = |a: ints[0], b: ints[1]| a.wrapping_add(b)),
        Op::SubI => lanes!(ints[2] = |a: ints[0], b: ints[1]| a.wrapping_sub(b)),
        Op::MinI => lanes!(ints[2] = |a: ints[0], b: ints[1]| a.min(b)),
        Op::MaxI => lanes!(ints[2] = |a: ints[0], b: ints[1]| a.max(b)),

        Op::And => lanes!(bools[2] = |a: bools[0], b: bools[1]| a && b),
        Op::Or => lanes!(bools[2] = |a: bools[0], b: bools[1]| a || b),
        Op::Xor => lanes!(bools[2] = |a: bools[0], b: bools[1]| a != b),
        Op::Not => lanes!(bools[1] = |a: bools[0]| !a),
        Op::LessF => lanes!(bools[2] = |a: floats[0], b: floats[1]| a < b),
        Op::LessEqualF => lanes!(bools[2] = |a: floats[0], b: floats[1]| a <= b),
        Op::GreaterF => lanes!(bools[2] = |a: floats[0], b: floats[1]| a > b),
        Op::GreaterEqualF => lanes!(bools[2] = |a: floats[0], b: floats[1]| a >= b),
        Op::LessI => lanes!(bools[2] = |a: ints[0], b: ints[1]| a < b),
        Op::LessEqualI => lanes!(bools[2] = |a: ints[0], b: ints[1]| a <= b),
        Op::GreaterI => lanes!(bools[2] = |a: ints[0], b: ints[1]| a > b),
        Op::GreaterEqualI => lanes!(bools[2] = |a: ints[0], b: ints[1]| a >= b),
        Op::Equals(Elem::Float) => lanes!(bools[2] = |a: floats[0], b: floats[1]| a == b),
        Op::NotEquals(Elem::Float) => lanes!(bools[2] = |a: floats[0], b: floats[1]| a != b),
        Op::Equals(Elem::Int) => lanes!(bools[2] = |a: ints[0], b: ints[1]| a == b),
        Op::NotEquals(Elem::Int) => lanes!(bools[2] = |a: ints[0], b: ints[1]| a != b),
        Op::Equals(Elem::Bool) => lanes!(bools[2] = |a: bools[0], b: bools[1]| a == b),
        Op::NotEquals(Elem::Bool) => lanes!(bools[2] = |a: bools[0], b: bools[1]| a != b),

        Op::Select(ty) | Op::Copy(ty) => {
            macro_rules! pick {
                ($a:ident) => {
                    if matches!(op, Op::Select(_)) {
                        select!($a)
                    } else {
                        copy!($a)
                    }
                };
            }
            match ty {
                ValueType::Bool => pick!(bools),
                ValueType::Int => pick!(ints),
                ValueType::Float => pick!(floats),
                ValueType::Vec3 => pick!(vec3s),
                ValueType::Quat => pick!(quats),
                ValueType::Transform => pick!(transforms),
                ValueType::Bone | ValueType::Name | ValueType::Array(_) => return false,
            }
        }

        Op::AddV => arith!(AddV, 0),
        Op::SubV => arith!(SubV, 0),
        Op::ScaleV => arith!(ScaleV, 0),
        Op::MulV => lanes!(vec3s[2] = |a: vec3s[0], b: vec3s[1]| a * b),
        Op::NegV => lanes!(vec3s[1] = |a: vec3s[0]| -a),
        Op::MinV => lanes!(vec3s[2] = |a: vec3s[0], b: vec3s[1]| a.min(b)),
        Op::MaxV => lanes!(vec3s[2] = |a: vec3s[0], b: vec3s[1]| a.max(b)),
        Op::AbsV => lanes!(vec3s[1] = |a: vec3s[0]| a.abs()),
        Op::LerpV => lanes!(vec3s[3] = |a: vec3s[0], b: vec3s[1], t: floats[2]| a.lerp(b, t)),
        // Lengths, distances and dot products on the vectors' components: glam's sums,
        // `(x + y) + z`, in the same order.
        Op::LengthV => {
            // SAFETY: as in `lanes!`; the output is of another type than the input.
            let [x, y, z] = vec3_columns(unsafe { &*block(lane0.vec3s, o[0]) });
            // SAFETY: as above.
            let out = unsafe { &mut *block(lane0.floats, o[1]) };
            for (m, r) in out.iter_mut().enumerate() {
                *r = ((x[m] * x[m] + y[m] * y[m]) + z[m] * z[m]).sqrt();
            }
        }
        Op::DistanceV => {
            // SAFETY: as above.
            let [ax, ay, az] = vec3_columns(unsafe { &*block(lane0.vec3s, o[0]) });
            let [bx, by, bz] = vec3_columns(unsafe { &*block(lane0.vec3s, o[1]) });
            // SAFETY: as above.
            let out = unsafe { &mut *block(lane0.floats, o[2]) };
            for (m, r) in out.iter_mut().enumerate() {
                let (x, y, z) = (ax[m] - bx[m], ay[m] - by[m], az[m] - bz[m]);
                *r = ((x * x + y * y) + z * z).sqrt();
            }
        }
        Op::DotV => {
            // SAFETY: as above.
            let [ax, ay, az] = vec3_columns(unsafe { &*block(lane0.vec3s, o[0]) });
            let [bx, by, bz] = vec3_columns(unsafe { &*block(lane0.vec3s, o[1]) });
            // SAFETY: as above.
            let out = unsafe { &mut *block(lane0.floats, o[2]) };
            for (m, r) in out.iter_mut().enumerate() {
                *r = (ax[m] * bx[m] + ay[m] * by[m]) + az[m] * bz[m];
            }
        }
        Op::CrossV => lanes!(vec3s[2] = |a: vec3s[0], b: vec3s[1]| a.cross(b)),
        Op::UnitV => lanes!(vec3s[1] = |a: vec3s[0]| k::unit_v(a)),
        Op::MakeVector => {
            // SAFETY: as in `lanes!`; the inputs are copies, of another type than the output.
            let xyz = unsafe { [0, 1, 2].map(|k| *block(lane0.floats, o[k])) };
            vec3_rows(&xyz, unsafe { &mut *block(lane0.vec3s, o[3]) });
        }
        Op::BreakVector => {
            // SAFETY: as above; `x`, `y` and `z` are written in that order (the last wins
            // when two are one slot, as in the handler).
            let xyz = vec3_columns(unsafe { &*block(lane0.vec3s, o[0]) });
            for (k, column) in [1, 2, 3].into_iter().zip(xyz) {
                // SAFETY: as above.
                unsafe { *block(lane0.floats, o[k]) = column };
            }
        }
        Op::RotateVector => {
            // SAFETY: as in `lanes!`; both blocks are read before the output is written.
            let (q, v) = unsafe { (&*block(lane0.quats, o[0]), &*block(lane0.vec3s, o[1])) };
            let (q, v) = (quat_columns(q), vec3_columns(v));
            let mut r = [[0.0; BATCH]; 3];
            for m in 0..BATCH {
                set_lane(&mut r, m, parts::rotate_parts(lane(&q, m), lane(&v, m)));
            }
            // SAFETY: as above.
            vec3_rows(&r, unsafe { &mut *block(lane0.vec3s, o[2]) });
        }
        Op::MakeTransform => {
            // SAFETY: as in `lanes!`; the inputs are of other types than the output.
            let (t, r, s) = unsafe {
                (
                    &*block(lane0.vec3s, o[0]),
                    &*block(lane0.quats, o[1]),
                    &*block(lane0.vec3s, o[2]),
                )
            };
            let r = quat_columns(r);
            let mut unit = [[0.0; BATCH]; 4];
            for m in 0..BATCH {
                set_lane(&mut unit, m, parts::unit_parts(lane(&r, m)));
            }
            let mut rotations = [Quat::IDENTITY; BATCH];
            quat_rows(&unit, &mut rotations);
            // SAFETY: as above; in another array than the inputs'.
            unsafe { put_transforms(block(lane0.transforms, o[3]), t, &rotations, s) };
        }
        // SAFETY: `o` is a `BreakTransform`'s operands (this function's contract).
        Op::BreakTransform => unsafe { break_transforms(o, lane0) },
        // The transform ops on component arrays compute with `parts`, glam's operations in
        // the order of its SSE2 code; where glam computes otherwise (`LANES_MATCH_GLAM`:
        // other processors, or `fma`), lane by lane with glam, as the handlers do.
        Op::TransformPoint if !LANES_MATCH_GLAM => {
            lanes!(vec3s[2] = |p: vec3s[1]; ref t: transforms[0]| t.transform_point(p))
        }
        Op::TransformVector if !LANES_MATCH_GLAM => {
            lanes!(vec3s[2] = |v: vec3s[1]; ref t: transforms[0]| t.transform_vector(v))
        }
        Op::MulT if !LANES_MATCH_GLAM => {
            lanes!(n, in place; transforms[2] = |a: transforms[0], b: transforms[1]| a * b)
        }
        Op::InverseT if !LANES_MATCH_GLAM => {
            lanes!(n, in place; transforms[1] = |a: transforms[0]| a.inverse())
        }
        Op::MakeRelative if !LANES_MATCH_GLAM => {
            lanes!(n, in place; transforms[2] = |a: transforms[0], b: transforms[1]|
            a.relative_to(&b))
        }
        Op::MakeAbsolute if !LANES_MATCH_GLAM => {
            lanes!(n, in place; transforms[2] = |a: transforms[0], b: transforms[1]| b * a)
        }
        // `translation + rotation · (scale ⊙ v)` on components, as glam computes it.
        Op::TransformPoint | Op::TransformVector => {
            // SAFETY: as in `lanes!`; the inputs are read before the output is written.
            let (t, v) = unsafe { (&*block(lane0.transforms, o[0]), &*block(lane0.vec3s, o[1])) };
            let (r, s, v) = (rotation_columns(t), scale_columns(t), vec3_columns(v));
            let position =
                (op == Op::TransformPoint).then(|| columns(t, |t| t.translation.to_array()));
            let mut moved = [[0.0; BATCH]; 3];
            for m in 0..BATCH {
                let scaled = std::array::from_fn(|c| s[c][m] * v[c][m]);
                let turned = parts::rotate_parts(lane(&r, m), scaled);
                set_lane(&mut moved, m, turned);
            }
            if let Some(p) = position {
                for (moved, p) in moved.iter_mut().zip(p) {
                    for (x, p) in moved.iter_mut().zip(p) {
                        *x += p;
                    }
                }
            }
            // SAFETY: as above.
            vec3_rows(&moved, unsafe { &mut *block(lane0.vec3s, o[2]) });
        }

        Op::MulFMulF => {
            arith!(MulF, 0);
            arith!(MulF, 3);
        }
        Op::SubFMulF => {
            arith!(SubF, 0);
            arith!(MulF, 3);
        }
        Op::MulFAddF => {
            arith!(MulF, 0);
            arith!(AddF, 3);
        }
        Op::SubFAddF => {
            arith!(SubF, 0);
            arith!(AddF, 3);
        }
        Op::AddFMulF => {
            arith!(AddF, 0);
            arith!(MulF, 3);
        }
        Op::MulFSubF => {
            arith!(MulF, 0);
            arith!(SubF, 3);
        }
        Op::AddFAddF => {
            arith!(AddF, 0);
            arith!(AddF, 3);
        }
        Op::DivFSubF => {
            arith!(DivF, 0);
            arith!(SubF, 3);
        }
        Op::AddVAddV => {
            arith!(AddV, 0);
            arith!(AddV, 3);
        }
        Op::AddVSubV => {
            arith!(AddV, 0);
            arith!(SubV, 3);
        }
        Op::MulFScaleV => {
            arith!(MulF, 0);
            arith!(ScaleV, 3);
        }
        Op::DivFScaleV => {
            arith!(DivF, 0);
            arith!(ScaleV, 3);
        }

        Op::SinF => lanes!(n, shared; floats[1] = |a: floats[0]| k::sin_deg(a)),
        Op::CosF => lanes!(n, shared; floats[1] = |a: floats[0]| k::cos_deg(a)),
        Op::TanF => lanes!(n, shared; floats[1] = |a: floats[0]| k::tan_deg(a)),
        Op::Atan2F => {
            lanes!(n, shared; floats[2] = |a: floats[0], b: floats[1]| k::atan2_deg(a, b))
        }
        Op::PowF => lanes!(n, shared; floats[2] = |a: floats[0], b: floats[1]| a.powf(b)),
        Op::FmodF => lanes!(n, shared; floats[2] = |a: floats[0], b: floats[1]| k::mod_f(a, b)),
        Op::FractF => lanes!(n, shared; floats[1] = |a: floats[0]| k::fract(a)),
        Op::FloorF => lanes!(n; floats[1] = |a: floats[0]| a.floor()),
        Op::CeilF => lanes!(n; floats[1] = |a: floats[0]| a.ceil()),
        Op::RoundF => lanes!(n; floats[1] = |a: floats[0]| a.round()),
        Op::ToInt => lanes!(ints[1] = |a: floats[0]| k::to_int(a)),
        Op::MulI => lanes!(ints[2] = |a: ints[0], b: ints[1]| a.wrapping_mul(b)),
        Op::DivI => lanes!(n, shared; ints[2] = |a: ints[0], b: ints[1]| k::div_i(a, b)),
        Op::ModI => lanes!(n, shared; ints[2] = |a: ints[0], b: ints[1]| k::mod_i(a, b)),
        Op::AbsI => lanes!(ints[1] = |a: ints[0]| a.wrapping_abs()),
        Op::NegI => lanes!(ints[1] = |a: ints[0]| a.wrapping_neg()),
        Op::ClampI => lanes!(ints[3] = |a: ints[0], lo: ints[1], hi: ints[2]| a.max(lo).min(hi)),
        Op::DivV => lanes!(vec3s[2] = |a: vec3s[0], b: vec3s[1]| k::div_v(a, b)),
        Op::ClampV => {
            lanes!(vec3s[3] = |a: vec3s[0], lo: vec3s[1], hi: vec3s[2]| a.max(lo).min(hi))
        }
        Op::ClampLength => lanes!(n, shared; vec3s[3] = |v: vec3s[0], lo: floats[1], hi: floats[2]|
            k::clamp_length(v, lo, hi)),
        Op::ClampSpatially => {
            lanes!(n, shared; vec3s[4] = |v: vec3s[0], c: vec3s[1], lo: floats[2],
            hi: floats[3]| k::clamp_spatially(v, c, lo, hi))
        }

        Op::QuatFromAxisAngle => {
            lanes!(n, shared; quats[2] = |; ref axis: vec3s[0], angle: floats[1]|
            k::quat_from_axis_angle(axis, angle))
        }
        Op::MulQ => lanes!(n, shared; quats[2] = |a: quats[0], b: quats[1]| k::unit_q(a * b)),
        Op::InverseQ => lanes!(n; quats[1] = |a: quats[0]| k::unit_q(a).inverse()),
        Op::UnitQ => lanes!(n; quats[1] = |a: quats[0]| k::unit_q(a)),
        Op::SlerpQ => {
            lanes!(n, shared; quats[3] = |a: quats[0], b: quats[1], t: floats[2]| k::slerp(a, b, t))
        }
        Op::QuatScale => {
            lanes!(n, shared; quats[2] = |a: quats[0], f: floats[1]| k::quat_scale(a, f))
        }
        Op::FindQuatBetween => lanes!(n, shared; quats[2] = |; ref a: vec3s[0], b: vec3s[1]|
            k::find_quat_between(a, b)),
        Op::MulT => {
            // SAFETY: as in `lanes!`; both blocks are read before the output is written.
            let out = unsafe {
                transform_products(
                    &*block(lane0.transforms, o[0]),
                    &*block(lane0.transforms, o[1]),
                )
            };
            // SAFETY: as above.
            unsafe { put_transform_rows(block(lane0.transforms, o[2]), &out) };
        }
        Op::InverseT => {
            // SAFETY: as in `lanes!`; the block is read before the output is written.
            let out = unsafe { transforms_relative(None, &*block(lane0.transforms, o[0])) };
            // SAFETY: as above.
            unsafe { put_transform_rows(block(lane0.transforms, o[1]), &out) };
        }
        Op::MakeRelative => {
            // SAFETY: as for `MulT`.
            let out = unsafe {
                transforms_relative(
                    Some(&*block(lane0.transforms, o[0])),
                    &*block(lane0.transforms, o[1]),
                )
            };
            // SAFETY: as above.
            unsafe { put_transform_rows(block(lane0.transforms, o[2]), &out) };
        }
        Op::MakeAbsolute => {
            // SAFETY: as for `MulT`; the parent's transform (operand 1) comes first.
            let out = unsafe {
                transform_products(
                    &*block(lane0.transforms, o[1]),
                    &*block(lane0.transforms, o[0]),
                )
            };
            // SAFETY: as above.
            unsafe { put_transform_rows(block(lane0.transforms, o[2]), &out) };
        }
        Op::RotateAroundPoint => {
            // `k::rotate_around_point` on component arrays: every input is read before the
            // output (which may be the transform's block) is written.
            // SAFETY: as in `lanes!`.
            let (t, p, r) = unsafe {
                (
                    &*block(lane0.transforms, o[0]),
                    &*block(lane0.vec3s, o[1]),
                    &*block(lane0.quats, o[2]),
                )
            };
            let position = columns(t, |t| t.translation.to_array());
            let rotation = rotation_columns(t);
            let (mut scale, at) = ([Vec3::ZERO; BATCH], t.as_ptr());
            // SAFETY: a local block; each scale is a transform's, padding after it, reached
            // through the whole block's pointer.
            unsafe { put_vec3s(&mut scale, |m| &raw const (*at.add(m)).scale) };
            let (p, r) = (vec3_columns(p), quat_columns(r));
            let (mut moved, mut turned) = ([[0.0; BATCH]; 3], [[0.0; BATCH]; 4]);
            for m in 0..BATCH {
                let r = parts::unit_parts(lane(&r, m));
                let (x, pivot) = (lane(&position, m), lane(&p, m));
                let arm = std::array::from_fn(|c| x[c] - pivot[c]);
                let swung = parts::rotate_parts(r, arm);
                set_lane(&mut moved, m, std::array::from_fn(|c| swung[c] + pivot[c]));
                let q = parts::mul_parts(r, lane(&rotation, m));
                set_lane(&mut turned, m, parts::unit_parts(q));
            }
            let (mut positions, mut rotations) = ([Vec3::ZERO; BATCH], [Quat::IDENTITY; BATCH]);
            vec3_rows(&moved, &mut positions);
            quat_rows(&turned, &mut rotations);
            // SAFETY: as above; the inputs were copied.
            unsafe {
                put_transforms(
                    block(lane0.transforms, o[3]),
                    &positions,
                    &rotations,
                    &scale,
                )
            };
        }

        Op::QuatFromEuler => lanes!(n, shared; quats[2] = |; ref euler: vec3s[0], order: ints[1]|
            strider_core::euler::quat_from_euler(euler, k::euler_order(order))),
        Op::EulerFromQuat => lanes!(n, shared; vec3s[2] = |; ref q: quats[0], order: ints[1]|
            strider_core::euler::euler_from_quat(q, k::euler_order(order))),
        Op::PerFootRotationFactor => lanes!(n, shared; floats[3] = |a: floats[0], b: floats[1],
            c: floats[2]| loco::per_foot_rotation_factor(a, b, c)),
        Op::LimitRotationAroundZ => lanes!(n, shared; quats[3] = |q: quats[0], a: floats[1],
            b: floats[2]| loco::limit_rotation_around_z(q, a, b)),
        Op::FootAvoidance => lanes!(n, shared; vec3s[5] = |a: vec3s[0], b: vec3s[1], c: floats[2],
            d: bools[3], e: floats[4]| loco::foot_avoidance(a, b, c, d, e)),
        Op::KneeVector => lanes!(n, shared; vec3s[5] = |a: quats[0], b: quats[1], c: vec3s[2],
            d: floats[3], e: floats[4]| loco::knee_vector(a, b, c, d, e)),
        Op::MovementAngleOffset => lanes!(n, shared; floats[8] = |velocity: vec3s[0], a: floats[1],
            b: floats[2], c: floats[3], d: floats[4], e: floats[5], f: floats[6], g: floats[7]; dt|
            loco::get_movement_angle_offset(velocity, a, b, dt, c, d, e, f, g)),
        Op::FootPivots => lanes!(n, shared; (ball => vec3s[6], tip => vec3s[7], heel => vec3s[8]) =
            |a: vec3s[0], b: vec3s[1], c: floats[2], d: floats[3], e: floats[4], f: floats[5]|
            loco::foot_pivots(a, b, c, d, e, f)),
        Op::PelvisLean => lanes!(n, shared; (pitch => floats[4], shift => floats[5]) =
            |v: vec3s[0], a: floats[1], b: floats[2], c: floats[3]| loco::pelvis_lean(v, a, b, c)),
        Op::RotationFromNormal => lanes!(n, shared;
        (pitch => floats[1], roll => floats[2], q => quats[3]) = |normal: vec3s[0]| {
            let (pitch, roll) = loco::rotation_from_normal(normal);
            (pitch, roll, loco::rotation_from_normal_quat(normal))
        }),
        Op::CycleStep => lanes!(n, shared; (master => floats[4], per_foot => floats[5]) =
            |a: floats[0], b: floats[1], c: floats[2], d: bools[3]; dt|
            loco::cycle_step(a, dt, b, c, d)),
        Op::ClavicleOffset => {
            lanes!(n, shared; floats[4] = |a: floats[0], b: floats[1], c: floats[2],
            d: floats[3]| loco::clavicle_offset(a, b, c, d))
        }
        Op::PelvisSideLean => {
            lanes!(n, shared; floats[3] = |a: floats[0], b: floats[1], c: floats[2]|
            loco::pelvis_side_lean(a, b, c))
        }
        Op::FootOffsetFromTrace => lanes!(n, shared; floats[3] = |hit: bools[0], a: floats[1],
            b: floats[2]| loco::foot_offset_from_trace(hit, a, b)),
        Op::ArmSwingRotation => lanes!(n, shared; floats[13] = |a: floats[0], b: vec3s[1],
            c: quats[2], d: floats[3], e: floats[4], f: floats[5], g: floats[6], h: floats[7],
            i: floats[8], j: floats[9], l: floats[10], m2: floats[11], p: floats[12]|
            loco::arm_swing_pitch(a, b, c, d, e, f, g, h, i, j, l, m2, p)),
        Op::AlignToNormal => lanes!(n, shared; transforms[4] = |t: transforms[0], axis: vec3s[1],
            normal: vec3s[2], weight: floats[3]| k::aim(t, axis, normal, weight)),

        Op::DeltaTime => {
            // SAFETY: as in `lanes!`.
            unsafe { *block(lane0.floats, o[0]) = *dts };
        }
        Op::FloatLerp => by_weight!(floats, loco::lerp_by_weight, BATCH),
        Op::VectorLerp => {
            // Operands: current, target, speed, most distance per second, result. Each
            // member's weight as in `by_weight!`, used where the member has no limit.
            // SAFETY: as in `lanes!`; the inputs are copies, so the output is the only
            // reference to its block.
            let (current, target, speed, most) = unsafe {
                (
                    *block(lane0.vec3s, o[0]),
                    *block(lane0.vec3s, o[1]),
                    *block(lane0.floats, o[2]),
                    *block(lane0.floats, o[3]),
                )
            };
            let alphas = weights(&speed, dts, n);
            // SAFETY: as above.
            let out = unsafe { &mut *block(lane0.vec3s, o[4]) };
            for (m, r) in out.iter_mut().enumerate().take(n) {
                *r = if most[m] > 0.0 {
                    loco::lerp_max_step(current[m], target[m], dts[m], speed[m], most[m])
                } else {
                    loco::lerp_by_weight_v(current[m], target[m], alphas[m])
                };
            }
        }
        Op::QuatLerp => by_weight!(quats, loco::slerp_by_weight, n),
        Op::FInterpToF => lanes!(n; floats[3] = |a: floats[0], b: floats[1], speed: floats[2]; dt|
            loco::finterp_to(a, b, dt, speed)),
        Op::FInterpToV => lanes!(n; vec3s[3] = |a: vec3s[0], b: vec3s[1], speed: floats[2]; dt|
            loco::vinterp_to(a, b, dt, speed)),
        Op::FInterpToQ => lanes!(n; quats[3] = |a: quats[0], b: quats[1], speed: floats[2]; dt|
            loco::qinterp_to(a, b, dt, speed)),
        _ => return false,
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exec::step;
    use crate::slots::{SCALAR_TYPES, Slots};
    use crate::tests::one_bone;
    use strider_core::{DebugDraw, Pose};
    use strider_nodes::{MAX_OPERANDS, Operand};

    /// Slots per scalar type in the tests' memory: every operand index stays below it.
    const SLOTS: usize = 16;

    #[test]
    fn lanes_agree_only_when_every_member_holds_the_same_bool() {
        let mut lanes = Lanes {
            bools: vec![false; 2 * BATCH],
            ..Lanes::default()
        };
        let set = |lanes: &mut Lanes, slot: usize, held: &[bool]| {
            lanes.bools[slot * BATCH..(slot + 1) * BATCH].copy_from_slice(held);
        };
        let agree = |lanes: &mut Lanes, slot: u32, n: usize| {
            // SAFETY: slots 0 and 1 are in the lanes.
            unsafe { agree(lanes.bases(), slot, n) }
        };
        set(&mut lanes, 1, &[true; BATCH]);
        for n in 1..=BATCH {
            assert_eq!(agree(&mut lanes, 0, n), Some(false), "{n} members");
            assert_eq!(agree(&mut lanes, 1, n), Some(true), "{n} members");
        }
        // One member differs: the lanes agree on `base` before it, disagree once it is
        // among them (unless it is alone).
        for odd in 0..BATCH {
            for (slot, base) in [(0, false), (1, true)] {
                let mut held = [base; BATCH];
                held[odd] = !base;
                set(&mut lanes, slot, &held);
                for n in 1..=BATCH {
                    let expected = match n {
                        n if n <= odd => Some(base),
                        1 => Some(!base),
                        _ => None,
                    };
                    assert_eq!(agree(&mut lanes, slot as u32, n), expected, "{odd} of {n}");
                }
            }
        }
    }

    /// A float for item `i` of member `m`: ordinary values mixed with the hazards a
    /// handler must treat the same lane by lane (signed zeros, NaN, infinities, huge and
    /// tiny values, negatives under a square root, zero divisors).
    fn float(m: usize, i: usize) -> f32 {
        const VALUES: [f32; 13] = [
            1.5,
            -2.25,
            0.0,
            -0.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1e30,
            -3.0e-39,
            7.0,
            0.125,
            -40.0,
            3.0,
        ];
        VALUES[(m * 7 + i * 5 + (m * i) % 3) % VALUES.len()]
    }

    /// Slots of member `m`: [`SLOTS`] of each scalar type, filled from [`float`].
    fn member_slots(m: usize) -> Slots {
        let f = |i: usize| float(m, i);
        let v = |i: usize| Vec3::new(f(3 * i), f(3 * i + 1), f(3 * i + 2));
        let q = |i: usize| Quat::from_xyzw(f(4 * i), f(4 * i + 1), f(4 * i + 2), f(4 * i + 3));
        const INTS: [i32; 6] = [0, -1, 5, i32::MIN, i32::MAX, 7];
        Slots {
            bools: (0..SLOTS).map(|i| (m + i).is_multiple_of(3)).collect(),
            ints: (0..SLOTS).map(|i| INTS[(m + 2 * i) % INTS.len()]).collect(),
            floats: (0..SLOTS).map(f).collect(),
            vec3s: (0..SLOTS).map(v).collect(),
            quats: (0..SLOTS).map(q).collect(),
            transforms: (0..SLOTS)
                .map(|i| Transform::new(v(i + 20), q(i + 20), v(i + 40)))
                .collect(),
            ..Slots::default()
        }
    }

    /// Member `m`'s time step (s): each member's its own, and one of them 0.
    fn dt(m: usize) -> f32 {
        [1.0 / 60.0, 0.5, 0.0, 1.0 / 30.0, 0.25][m % 5] * (1.0 + m as f32 / 16.0)
    }

    /// Operands for `op`'s layout: distinct slots per type, or with `in_place` each output
    /// in the slot of the first input of its type (as slot sharing may lay them out).
    fn operands(op: Op, in_place: bool) -> Option<Vec<u32>> {
        let layout = op.operands()?;
        let mut next = [1u32; 16];
        let mut first_input: Vec<(ValueType, u32)> = Vec::new();
        let mut o: Vec<u32> = layout
            .iter()
            .map(|operand| match *operand {
                Operand::Slot(ty, access) => {
                    let kind = ValueType::ALL
                        .iter()
                        .position(|t| *t == ty)
                        .expect("every type is in ALL");
                    let reuse = first_input.iter().find(|(t, _)| *t == ty).map(|&(_, s)| s);
                    match (access, reuse) {
                        (strider_nodes::Access::Write, Some(slot)) if in_place => slot,
                        _ => {
                            let slot = next[kind];
                            next[kind] += 1;
                            if access != strider_nodes::Access::Write {
                                first_input.push((ty, slot));
                            }
                            slot
                        }
                    }
                }
                Operand::Target => 0,
            })
            .collect();
        assert!(o.iter().all(|&s| (s as usize) < SLOTS));
        o.resize(o.len() + MAX_OPERANDS, 0);
        Some(o)
    }

    /// Runs `f` on contexts over `slots` (each with a pose and a debug buffer of its own).
    fn with_contexts(slots: &mut [Slots], f: impl FnOnce(&mut [Ctx<'_>])) {
        let mut poses = vec![Pose::new(one_bone()); slots.len()];
        let mut draws: Vec<DebugDraw> = slots.iter().map(|_| DebugDraw::new(false)).collect();
        let mut cxs: Vec<Ctx<'_>> = slots
            .iter_mut()
            .zip(&mut poses)
            .zip(&mut draws)
            .enumerate()
            .map(|(m, ((s, p), d))| Ctx::for_test(s, &[], p, d, dt(m)))
            .collect();
        f(&mut cxs);
    }

    /// Runs `op` on `n` members lane-wide; `None` when it is not a wide op. The lanes hold
    /// other values beyond the members (as after a larger batch).
    fn wide(op: Op, o: &[u32], n: usize, source: Source) -> Option<Vec<Slots>> {
        let lens = ScalarLens([SLOTS; 6]);
        let mut lanes = Lanes::default();
        let mut stale: Vec<Slots> = (0..BATCH).map(|m| member_slots(m + 100)).collect();
        with_contexts(&mut stale, |cxs| lanes.load(Copies::all(&lens), cxs));
        let mut members: Vec<Slots> = (0..n).map(|m| member_slots((source.slots)(m))).collect();
        let mut ran = false;
        with_contexts(&mut members, |cxs| {
            lanes.load(Copies::all(&lens), cxs);
            // SAFETY: the operands are slots below `SLOTS` of the lanes loaded above.
            let dts = std::array::from_fn(|m| if m < n { dt((source.dt)(m)) } else { 7.0 });
            ran = unsafe { run_wide(op, o, lanes.bases(), n, &dts) };
            lanes.store(Copies::all(&lens), cxs);
        });
        ran.then_some(members)
    }

    /// Which member's slots ([`member_slots`]) and time step ([`dt`]) each member gets.
    #[derive(Clone, Copy)]
    struct Source {
        slots: fn(usize) -> usize,
        dt: fn(usize) -> usize,
    }

    /// Members in runs: 0, 0, 0, 3, 3, 2, 2, 2, … (a run may come back to an earlier value).
    fn run(m: usize) -> usize {
        [0, 0, 0, 3, 3, 2, 2, 2, 4, 4, 5, 3, 3, 1, 1, 1][m]
    }

    /// Runs `op` on each of `n` members alone, with the executor's handler.
    fn alone(op: Op, o: &[u32], n: usize, source: Source) -> Vec<Slots> {
        (0..n)
            .map(|m| {
                let mut slots = member_slots((source.slots)(m));
                let mut pose = Pose::new(one_bone());
                let mut debug = DebugDraw::new(false);
                let dt = dt((source.dt)(m));
                let mut cx = Ctx::for_test(&mut slots, &[], &mut pose, &mut debug, dt);
                // SAFETY: the operands are slots below `SLOTS`, which the slots have.
                unsafe { step(op, o, &mut cx, 1) };
                slots
            })
            .collect()
    }

    /// Every scalar slot bit for bit, except that any NaN equals any NaN: which operand's
    /// NaN an operation passes on (its sign and payload) is left open by Rust, and
    /// vectorised code may pick the other one.
    fn same_values(a: &Slots, b: &Slots) -> bool {
        fn bits(x: f32) -> u32 {
            if x.is_nan() {
                f32::NAN.to_bits()
            } else {
                x.to_bits()
            }
        }
        fn same<T>(a: &[T], b: &[T], floats: impl Fn(&T) -> Vec<f32>) -> bool {
            a.len() == b.len()
                && a.iter().zip(b).all(|(x, y)| {
                    floats(x)
                        .into_iter()
                        .map(bits)
                        .eq(floats(y).into_iter().map(bits))
                })
        }
        a.bools == b.bools
            && a.ints == b.ints
            && same(&a.floats, &b.floats, |x| vec![*x])
            && same(&a.vec3s, &b.vec3s, |x| x.to_array().to_vec())
            && same(&a.quats, &b.quats, |x| x.to_array().to_vec())
            && same(&a.transforms, &b.transforms, |x| {
                x.to_bits().map(f32::from_bits).to_vec()
            })
    }

    #[test]
    fn every_wide_op_gives_each_lane_what_its_handler_gives_one_member() {
        let mut count = 0;
        for op in crate::tests::every_op() {
            for in_place in [false, true] {
                // Ops without a layout are ones no program holds.
                let Some(o) = operands(op, in_place) else {
                    continue;
                };
                // Members with slots and time steps of their own; members in runs with
                // the same slots and time steps; the same slots but time steps of their
                // own (kernels run once per run may not reuse a result across a change).
                let own = Source {
                    slots: |m| m,
                    dt: |m| m,
                };
                let runs = Source {
                    slots: run,
                    dt: run,
                };
                let own_dt = Source {
                    slots: run,
                    dt: |m| m,
                };
                // A whole batch alike (kernels run once for all), and alike but for the
                // last member's slots or time step (every slot of member 1 differs from
                // member 0's; member 2's slots give the kernels that read the time step
                // results that depend on it).
                let alike = Source {
                    slots: |_| 0,
                    dt: |_| 0,
                };
                let last_slots = Source {
                    slots: |m| usize::from(m == BATCH - 1),
                    dt: |_| 0,
                };
                let last_dt = Source {
                    slots: |_| 2,
                    dt: |m| usize::from(m == BATCH - 1),
                };
                for (n, source) in [
                    (BATCH, own),
                    (5, own),
                    (BATCH, runs),
                    (BATCH, own_dt),
                    (BATCH, alike),
                    (BATCH, last_slots),
                    (BATCH, last_dt),
                ] {
                    let Some(lanes) = wide(op, &o, n, source) else {
                        continue;
                    };
                    // Only ops that compute scalar slots from scalar slots may run wide.
                    for &operand in op.operands().expect("a layout").iter() {
                        assert!(
                            matches!(operand, Operand::Slot(ty, _) if SCALAR_TYPES.contains(&ty)),
                            "{op:?} runs wide with operand {operand:?}"
                        );
                    }
                    let reference = alone(op, &o, n, source);
                    for (m, (a, b)) in lanes.iter().zip(&reference).enumerate() {
                        assert!(
                            same_values(a, b),
                            "{op:?} (in place: {in_place}): member {m} of {n} differs from \
                             the handler run alone"
                        );
                    }
                    if !in_place && n == BATCH && (source.slots)(1) == 1 {
                        count += 1;
                    }
                }
            }
        }
        // The 138 ops `run_wide` has arms for (a miss here means `every_op` lacks one).
        assert_eq!(count, 138);
    }

    /// A select takes each lane from the block its condition names, whether every lane
    /// names the same block (copied whole) or not, and also when the result's block is one
    /// of the choices.
    #[test]
    fn selects_take_each_lane_from_the_chosen_block() {
        let x: [Vec3; BATCH] = std::array::from_fn(|m| Vec3::splat(m as f32));
        let y: [Vec3; BATCH] = std::array::from_fn(|m| Vec3::splat(-(m as f32) - 1.0));
        let mixed: [bool; BATCH] = std::array::from_fn(|m| m % 3 == 1);
        for c in [[true; BATCH], [false; BATCH], mixed] {
            let want: [Vec3; BATCH] = std::array::from_fn(|m| if c[m] { x[m] } else { y[m] });
            let (mut a, mut b, mut out) = (x, y, [Vec3::NAN; BATCH]);
            // SAFETY: three blocks of `BATCH` items each.
            unsafe { select_items(c, &raw mut a, &raw mut b, &raw mut out) };
            assert_eq!(out, want, "into a block of its own");
            // SAFETY: as above; the result in the first choice's block.
            unsafe { select_items(c, &raw mut a, &raw mut b, &raw mut a) };
            assert_eq!(a, want, "into the first choice");
            let mut a = x;
            // SAFETY: as above; the result in the second choice's block.
            unsafe { select_items(c, &raw mut a, &raw mut b, &raw mut b) };
            assert_eq!(b, want, "into the second choice");
        }
    }

    /// A block is uniform only when every lane holds lane 0's bits: one lane that differs
    /// in one component (a sign of zero, a NaN's payload, a transform's last scale) is
    /// found wherever it is.
    #[test]
    fn uniform_blocks_are_told_from_blocks_with_one_lane_apart() {
        fn check<T: Uniform + Copy>(same: T, other: T, what: &str) {
            assert!(Uniform::uniform(&[same; BATCH]), "{what}: alike");
            for m in 0..BATCH {
                let mut block = [same; BATCH];
                block[m] = other;
                assert!(!Uniform::uniform(&block), "{what}: lane {m} apart");
            }
        }
        let nan = f32::from_bits(0x7fc0_0001);
        check(0.0f32, -0.0, "zero");
        check(nan, f32::from_bits(0x7fc0_0002), "NaN payload");
        check(3i32, -3, "int");
        check(true, false, "bool");
        check(
            Vec3::new(1.0, 2.0, nan),
            Vec3::new(1.0, 2.0, -nan),
            "vector",
        );
        check(
            Quat::from_xyzw(0.0, 0.0, 0.0, 1.0),
            Quat::from_xyzw(0.0, 0.0, -0.0, 1.0),
            "rotation",
        );
        let t = Transform::new(Vec3::X, Quat::IDENTITY, Vec3::ONE);
        let mut scaled = t;
        scaled.scale.z = 1.0 + f32::EPSILON;
        check(t, scaled, "transform");
    }

    /// A vector with distinct bits in every component: `-0.0`, a NaN with a payload, and
    /// values that differ from lane to lane.
    fn odd_vec3(k: usize) -> Vec3 {
        let k = k as u32;
        Vec3::new(
            f32::from_bits(0x8000_0000 | k),
            f32::from_bits(0x7fc0_0000 | (k << 4) | 1),
            k as f32 + 0.5,
        )
    }

    /// The 16-byte copies of `put_vec3s` and `put_transforms` give every lane its value, bit
    /// for bit, and write nothing past the block: the item after it (a guard, as the next
    /// slot's block would be) keeps its bits.
    #[test]
    fn wide_vector_copies_give_every_lane_its_bits_and_stop_at_the_block() {
        let bits = |v: Vec3| v.to_array().map(f32::to_bits);
        let transforms: [Transform; BATCH] = std::array::from_fn(|m| {
            Transform::new(
                odd_vec3(m),
                Quat::from_rotation_z(m as f32),
                odd_vec3(100 + m),
            )
        });
        let guard = Vec3::new(7.0, 8.0, 9.0);
        let at = transforms.as_ptr();
        // The translations, then the scales.
        type Part = fn(&Transform) -> Vec3;
        let parts: [(Part, usize); 2] = [
            (
                |x| x.translation,
                std::mem::offset_of!(Transform, translation),
            ),
            (|x| x.scale, std::mem::offset_of!(Transform, scale)),
        ];
        for (part, offset) in parts {
            let mut vectors = [guard; BATCH + 1];
            let out: *mut [Vec3; BATCH] = vectors.as_mut_ptr().cast();
            let from = |m: usize| at.wrapping_add(m).cast::<u8>().wrapping_add(offset).cast();
            // SAFETY: `out` is the first BATCH items; each part has padding after it, and
            // is reached through the whole block's pointer.
            unsafe { put_vec3s(out, from) };
            for m in 0..BATCH {
                assert_eq!(bits(vectors[m]), bits(part(&transforms[m])), "lane {m}");
            }
            assert_eq!(bits(vectors[BATCH]), bits(guard), "past the block");
        }

        let (t, s): ([Vec3; BATCH], [Vec3; BATCH]) = (
            std::array::from_fn(odd_vec3),
            std::array::from_fn(|m| odd_vec3(50 + m)),
        );
        let r: [Quat; BATCH] = std::array::from_fn(|m| Quat::from_rotation_x(m as f32));
        let guard = Transform::new(guard, Quat::IDENTITY, guard);
        let mut blocks = [guard; BATCH + 1];
        // SAFETY: the first BATCH items; the inputs are other arrays.
        unsafe { put_transforms(blocks.as_mut_ptr().cast(), &t, &r, &s) };
        for m in 0..BATCH {
            let x = blocks[m];
            assert_eq!(bits(x.translation), bits(t[m]), "lane {m}");
            assert_eq!(x.rotation.to_array(), r[m].to_array(), "lane {m}");
            assert_eq!(bits(x.scale), bits(s[m]), "lane {m}");
        }
        assert!(blocks[BATCH].bit_eq(&guard), "past the block");
    }

    /// The exponential lerps compute their weight once per run of members with the same
    /// speed and time step: each member still gets `lerp_exponential` of its own speed
    /// and dt, whatever its neighbours have (runs broken by the speed, by dt, by `-0.0`
    /// against `0.0` and by NaN).
    #[test]
    fn exponential_lerps_reuse_a_weight_only_for_equal_speed_and_time_step() {
        const NAN: f32 = f32::NAN;
        let speeds: [f32; BATCH] = [
            4.0, 4.0, 4.0, 4.0, 2.0, 2.0, 4.0, 4.0, 4.0, -0.0, 0.0, NAN, NAN, 1e30, 4.0, 4.0,
        ];
        let (a, b) = (1.0 / 60.0, 1.0 / 30.0);
        let dts: [f32; BATCH] = [a, a, a, b, a, a, a, a, 0.0, a, a, a, a, a, a, a];
        let lens = ScalarLens([SLOTS; 6]);
        // Floats: 1 current, 2 target, 3 speed, 4 result; quats the same.
        let mut members: Vec<Slots> = (0..BATCH)
            .map(|m| {
                let mut slots = member_slots(m);
                slots.floats[1] = m as f32 - 3.0;
                slots.floats[2] = 10.0;
                slots.floats[3] = speeds[m];
                slots.quats[1] = Quat::from_rotation_z(0.1 * m as f32);
                slots.quats[2] = Quat::from_rotation_x(1.0);
                slots
            })
            .collect();
        let mut o = vec![1, 2, 3, 4];
        o.resize(o.len() + MAX_OPERANDS, 0);
        let mut lanes = Lanes::default();
        with_contexts(&mut members, |cxs| {
            lanes.load(Copies::all(&lens), cxs);
            for op in [Op::FloatLerp, Op::QuatLerp] {
                // SAFETY: the operands are slots below `SLOTS` of the lanes loaded above.
                assert!(unsafe { run_wide(op, &o, lanes.bases(), BATCH, &dts) });
            }
            lanes.store(Copies::all(&lens), cxs);
        });
        for (m, slots) in members.iter().enumerate() {
            let want = loco::lerp_exponential(m as f32 - 3.0, 10.0, dts[m], speeds[m]);
            assert_eq!(
                slots.floats[4].to_bits(),
                want.to_bits(),
                "float, member {m}"
            );
            let want = loco::lerp_exponential_q(
                Quat::from_rotation_z(0.1 * m as f32),
                Quat::from_rotation_x(1.0),
                dts[m],
                speeds[m],
            );
            assert_eq!(
                slots.quats[4].to_array(),
                want.to_array(),
                "quat, member {m}"
            );
        }
    }

    #[test]
    fn axis_angle_rotations_are_reused_only_for_equal_axis_and_angle() {
        const NAN: f32 = f32::NAN;
        let angles: [f32; BATCH] = [
            0.0, 0.0, 0.0, -0.0, -0.0, 30.0, 30.0, 30.0, NAN, NAN, 30.0, 1e30, 1e30, 0.0, 0.0, 0.0,
        ];
        let (z, x) = (Vec3::Z, Vec3::X);
        let axes: [Vec3; BATCH] = [z, z, x, x, x, x, z, z, z, z, z, z, z, z, Vec3::ZERO, z];
        let lens = ScalarLens([SLOTS; 6]);
        // Vector 1 the axis, float 2 the angle, rotation 3 the result.
        let mut members: Vec<Slots> = (0..BATCH)
            .map(|m| {
                let mut slots = member_slots(m);
                slots.vec3s[1] = axes[m];
                slots.floats[2] = angles[m];
                slots
            })
            .collect();
        let mut o = vec![1, 2, 3];
        o.resize(o.len() + MAX_OPERANDS, 0);
        let mut lanes = Lanes::default();
        with_contexts(&mut members, |cxs| {
            lanes.load(Copies::all(&lens), cxs);
            // SAFETY: the operands are slots below `SLOTS` of the lanes loaded above.
            assert!(unsafe {
                run_wide(
                    Op::QuatFromAxisAngle,
                    &o,
                    lanes.bases(),
                    BATCH,
                    &[0.0; BATCH],
                )
            });
            lanes.store(Copies::all(&lens), cxs);
        });
        for (m, slots) in members.iter().enumerate() {
            let want = k::quat_from_axis_angle(axes[m], angles[m]);
            let got = slots.quats[3].to_array().map(f32::to_bits);
            assert_eq!(got, want.to_array().map(f32::to_bits), "member {m}");
        }
    }

    #[test]
    fn lanes_load_and_store_every_scalar_slot_of_every_member() {
        let lens = ScalarLens([3, 4, 5, 6, 7, 8]);
        let mut members: Vec<Slots> = (0..BATCH).map(member_slots).collect();
        let before = members.clone();
        with_contexts(&mut members, |cxs| {
            let mut lanes = Lanes::default();
            lanes.load(Copies::all(&lens), cxs);
            // Slot 2 of member 9 is item 2 * BATCH + 9 of its type's lane array.
            assert_eq!(lanes.floats[2 * BATCH + 9].to_bits(), float(9, 2).to_bits());
            assert_eq!(lanes.ints.len(), 4 * BATCH);
            assert_eq!(lanes.transforms.len(), 8 * BATCH);
            lanes.floats[2 * BATCH + 9] = 42.0;
            lanes.store(Copies::all(&lens), cxs);
        });
        assert_eq!(members[9].floats[2], 42.0);
        members[9].floats[2] = before[9].floats[2];
        for (a, b) in members.iter().zip(&before) {
            assert!(a.bit_eq(b), "everything else comes back as it was");
        }
    }
}
