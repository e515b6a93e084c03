//! The executor: a `match` loop over a program's instructions, for one instance ([`run`])
//! or for a batch of instances of one program together ([`run_batch`]).
//!
//! Handlers trust the program: operand counts and slot types match each op's layout
//! ([`Op::operands`]). Scalar slots (bools, ints, floats, vectors, rotations, transforms)
//! are read and written without bounds checks, which is sound because:
//! - [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) gives every scalar slot
//!   array of the program's initial memory a slot for every operand that the op's layout
//!   types as a slot of that type, so an instruction's slot operands are in bounds of the
//!   initial image;
//! - every run of an event first checks that the instance's arrays are still at least that
//!   long (growing them if not: `Instance::event_context`, for each member of a batch
//!   too), and nothing shrinks them during a run; a batch runs on lanes
//!   ([`crate::lanes`]) of [`BATCH`] times the program's lengths, loaded from those arrays;
//! - each handler reads operand `k` only through the accessor of the type the op's layout
//!   gives position `k` (every access asserts its bound in debug builds, where the test
//!   suite runs every op).
//!
//! Instructions and their operand windows are fetched without bounds checks too:
//! `ProgramBuilder::finish` makes sure every jump target and event entry is an
//! instruction, that the last instruction cannot fall through past the end, and pads the
//! operand list by `MAX_OPERANDS` past every instruction's first operand.
//!
//! Bones, names and the elements of arrays keep their bounds checks. Array variables keep
//! theirs here too; `ProgramBuilder::finish` makes sure every array operand names one of
//! the program's, which the batch's array reads and writes rely on (`per_member`).

// Unchecked slot access and instruction fetch (see above) are this module's only unsafe
// code.
#![allow(unsafe_code)]

#[cfg(target_arch = "x86_64")]
use crate::batch_code::{BatchCode, batch_code};
use crate::lanes::{Copies, LANES, Lanes};
use crate::program::{Instr, Program};
use crate::slots::{ScalarLens, Slots};
use glam::{Affine3A, Quat, Vec3, Vec3A};
use strider_core::{
    BoneIndex, DebugColor, DebugDraw, DebugPrimitive, LineQuery, Pose, SphereQuery, TraceHit,
    Transform, WorldQuery, all_finite, load_vec3,
};
use strider_nodes::kernels as k;
use strider_nodes::kernels::locomotion as loco;
use strider_nodes::kernels::spline::{self, SplineMode};
use strider_nodes::kernels::two_bone_ik::{BoneAxes, Pole, TwoBoneIk};
use strider_nodes::{Elem, MAX_OPERANDS, Op, ValueType};

/// What one run of an event works on.
pub(crate) struct Ctx<'a> {
    pub slots: &'a mut Slots,
    /// The program's text table (names read by `FindBones`).
    pub texts: &'a [String],
    pub pose: &'a mut Pose,
    pub debug: &'a mut DebugDraw,
    pub world: &'a dyn WorldQuery,
    pub dt: f32,
    pub to_world: Transform,
    /// `to_world` as a matrix ([`Transform::to_affine`]), computed once per run of a
    /// program that traces (the identity otherwise): traces map their ends to world space.
    pub to_world_matrix: Affine3A,
    /// `to_world.inverse()` as a matrix, as `to_world_matrix`: traces bring hits back to
    /// rig space.
    pub from_world_matrix: Affine3A,
    /// Number of this run (construction or frame), never 0: stateful nodes advance once per
    /// run and remember the run they last advanced in.
    pub run: i32,
    /// The run's path key, written when the run ends: the jumps it took, in order, folded
    /// by [`next_path`]. Two runs through the same instructions have the same key, whether
    /// they ran alone or batched; `Instance::run_forward_batch` batches instances whose last
    /// frames had the same key, which likely take one path again.
    pub path: u64,
    /// The run's jump sites, written when the run ends: bit [`site_bit`] of every
    /// instruction it jumped from (`Instance::jump_sites`).
    pub taken: u64,
    /// Where to accumulate per-instruction time and counts (indexed by instruction), when
    /// profiling is on.
    #[cfg(feature = "profile")]
    pub profile: Option<&'a mut [crate::profile::InstrProfile]>,
}

#[cfg(test)]
impl<'a> Ctx<'a> {
    /// A run's context for tests: no world, the character at the origin, run 1.
    pub(crate) fn for_test(
        slots: &'a mut Slots,
        texts: &'a [String],
        pose: &'a mut Pose,
        debug: &'a mut DebugDraw,
        dt: f32,
    ) -> Self {
        Self {
            slots,
            texts,
            pose,
            debug,
            world: &strider_core::EmptyWorld,
            dt,
            to_world: Transform::IDENTITY,
            to_world_matrix: Affine3A::IDENTITY,
            from_world_matrix: Affine3A::IDENTITY,
            run: 1,
            path: 0,
            taken: 0,
            #[cfg(feature = "profile")]
            profile: None,
        }
    }
}

/// A run's path key ([`Ctx::path`]) `path` after a jump from instruction `pc`: the key
/// turned by 5 bits, the instruction's number mixed in, and the whole multiplied by the
/// golden ratio's 64-bit constant (FxHash's step). The turn makes the key depend on the
/// jumps' order, not only on which were taken: a character whose left foot is planted
/// and right foot swinging takes the same jumps as one the other way round, in another
/// order, and the two part ways inside every loop over the feet. The multiplication
/// keeps the key from being a linear function of the jumps (with turns and exclusive-ors
/// alone, loops whose trip counts differ by 64 could fold to one key).
#[inline(always)]
pub(crate) fn next_path(path: u64, pc: usize) -> u64 {
    (path.rotate_left(5) ^ (pc as u64 + 1)).wrapping_mul(0x9E37_79B9_7F4A_7C15)
}

/// The bit of a run's jump sites ([`Ctx::taken`]) for a jump from instruction `pc`: bit
/// `pc % 64` (a jump's instruction index is as good a spread as a hash of it, and cheaper).
#[inline(always)]
pub(crate) fn site_bit(pc: usize) -> u64 {
    1 << (pc % 64)
}

/// A bone slot's value as an index into the pose, if it names a bone.
#[inline]
pub(crate) fn bone(pose: &Pose, value: i32) -> Option<BoneIndex> {
    (value >= 0 && (value as usize) < pose.len()).then_some(BoneIndex(value as u32))
}

/// `ArrayAt`'s element: item `index` of `array`, or `zero` (the element type's default)
/// for a negative index or one at or past the end. The item or the default is chosen by
/// reference and copied once (a transform is 48 bytes).
#[inline(always)]
pub(crate) fn array_get<T: Copy>(array: &[T], index: i32, zero: &T) -> T {
    let item = if index >= 0 {
        array.get(index as usize)
    } else {
        None
    };
    *item.unwrap_or(zero)
}

/// `ArraySetAt`: item `index` of `array` becomes `value`; a negative index, or one at or
/// past the end, changes nothing.
#[inline(always)]
pub(crate) fn array_set<T>(array: &mut [T], index: i32, value: T) {
    if index >= 0
        && let Some(x) = array.get_mut(index as usize)
    {
        *x = value;
    }
}

/// `GetTransform`'s result: the transform of bone `bone` (a bone slot's value: an index
/// into the pose, -1 or out of range for none), global (rig space) when `space` is 0, else
/// local (parent space); the skeleton's rest transform when `initial`, else the pose's (a
/// stale global is computed first, hence `&mut`). The identity for no bone.
#[inline(always)]
pub(crate) fn bone_transform(pose: &mut Pose, bone: i32, space: i32, initial: bool) -> Transform {
    match self::bone(pose, bone) {
        None => Transform::IDENTITY,
        Some(bi) => match (initial, space == 0) {
            (true, true) => pose.skeleton().rest_global(bi),
            (true, false) => pose.skeleton().rest_local(bi),
            (false, true) => pose.global(bi),
            (false, false) => pose.local(bi),
        },
    }
}

/// `SetTransform`: bone `bone`'s transform blended towards `value` by `weight` (0 keeps
/// it, 1 sets it), global (rig space, children following when `propagate`) when `space`
/// is 0, else local (parent space).
#[inline(always)]
fn set_transform(
    pose: &mut Pose,
    bone: BoneIndex,
    value: Transform,
    space: i32,
    propagate: bool,
    weight: f32,
) {
    if space == 0 {
        let value = k::blend_transform(pose.global(bone), value, weight);
        pose.set_global(bone, value, propagate);
    } else {
        let value = k::blend_transform(pose.local(bone), value, weight);
        pose.set_local(bone, value);
    }
}

/// `GetParent`: the bone slot value of bone `bone`'s parent (a bone slot's value), -1 for
/// a root or no bone.
#[inline(always)]
pub(crate) fn parent_of(pose: &Pose, bone: i32) -> i32 {
    match self::bone(pose, bone) {
        Some(bi) => pose.skeleton().parent(bi).map_or(-1, |p| p.0 as i32),
        None => -1,
    }
}

fn color(v: Vec3) -> DebugColor {
    DebugColor([v.x, v.y, v.z, 1.0])
}

/// Dispatches a per-element-type handler: `$m!(scalars, arrays, zero)`, where
/// `$sc` names the scalar slots of the element type (read and written with `scalar!`
/// inside [`execute!`]), `$ar` is its array slots.
macro_rules! by_elem {
    ($e:expr, $s:expr, $m:ident) => {
        match $e {
            Elem::Bool => $m!(bools, $s.bool_arrays, false),
            Elem::Int => $m!(ints, $s.int_arrays, 0),
            Elem::Float => $m!(floats, $s.float_arrays, 0.0),
            Elem::Vec3 => $m!(vec3s, $s.vec3_arrays, Vec3::ZERO),
            Elem::Quat => $m!(quats, $s.quat_arrays, Quat::IDENTITY),
            Elem::Transform => $m!(transforms, $s.transform_arrays, Transform::IDENTITY),
            Elem::Bone => $m!(bones, $s.bone_arrays, -1),
        }
    };
}

/// Runs `$body` with `$c` bound to the constant element type `$e` holds, so that the
/// `by_elem!` dispatch inside `$body` folds away: one `match` per instruction rather than
/// one per batch member.
macro_rules! with_elem {
    ($e:expr, $c:ident => $body:expr) => {
        with_elem!(@each $e, $c, $body, Bool Int Float Vec3 Quat Transform Bone)
    };
    (@each $e:expr, $c:ident, $body:expr, $($v:ident)+) => {
        match $e {
            $(Elem::$v => {
                const $c: Elem = Elem::$v;
                $body
            })+
        }
    };
}

/// Copies within one slot array; arrays reuse the destination's memory.
fn copy_vec<T: Copy>(v: &mut [Vec<T>], from: usize, to: usize) {
    let (source, target) = match from.cmp(&to) {
        std::cmp::Ordering::Equal => return,
        std::cmp::Ordering::Less => {
            let (low, high) = v.split_at_mut(to);
            (&low[from], &mut high[0])
        }
        std::cmp::Ordering::Greater => {
            let (low, high) = v.split_at_mut(from);
            (&high[0], &mut low[to])
        }
    };
    target.clear();
    target.extend_from_slice(source);
}

/// Runs a handler body once, on the one instance at hand (the `$each` of [`execute!`] for
/// a single instance).
macro_rules! once {
    ($body:expr) => {
        $body
    };
}

/// Leaves alone what an array variable's write would change elsewhere (the `$forget` of
/// [`execute!`] for a run on an instance's own slots, which has no copies of its arrays).
macro_rules! keep {
    ($elem:expr, $array:expr) => {{
        let _ = ($elem, $array);
    }};
}

/// A trace's hit as SIMD vectors (point, normal) and its distance, or `None` for a miss
/// or a hit with a non-finite component. Read where the world returned it: its vectors
/// with [`load_vec3`], as stored, not copied out first (a copy reads 16 bytes at a time
/// across the answer's separate stores, and waits for them to reach the cache).
#[inline(always)]
pub(crate) fn read_hit(hit: &Option<TraceHit>) -> Option<(Vec3A, Vec3A, f32)> {
    let h = hit.as_ref()?;
    let (point, normal) = (load_vec3(&h.point), load_vec3(&h.normal));
    all_finite([point, normal, Vec3A::splat(h.distance)]).then_some((point, normal, h.distance))
}

/// A trace node's ends (rig space) taken to world space by `to_world`.
#[inline(always)]
pub(crate) fn trace_ends(to_world: &Affine3A, start: Vec3, end: Vec3) -> LineQuery {
    LineQuery {
        start: to_world.transform_point3(start),
        end: to_world.transform_point3(end),
    }
}

/// A sphere trace node's question to the world: its ends taken to world space
/// ([`trace_ends`]), and its radius (cm) made 0 where it is below 0 or NaN.
#[inline(always)]
pub(crate) fn trace_query(to_world: &Affine3A, start: Vec3, end: Vec3, radius: f32) -> SphereQuery {
    let LineQuery { start, end } = trace_ends(to_world, start, end);
    SphereQuery {
        start,
        end,
        radius: radius.max(0.0),
    }
}

/// A trace node's outputs (hit, point, normal, distance; rig space) from the world's answer
/// ([`read_hit`]) to the trace from `start` to `end` (rig space), `from_world` taking
/// world space to rig space: the hit mapped back, or for a miss the end, `+Z` and the
/// whole length.
#[inline(always)]
pub(crate) fn trace_outputs(
    hit: Option<(Vec3A, Vec3A, f32)>,
    start: Vec3,
    end: Vec3,
    from_world: &Affine3A,
) -> (bool, Vec3, Vec3, f32) {
    match hit {
        Some((point, normal, distance)) => (
            true,
            from_world.transform_point3a(point).into(),
            // Normalised in SIMD registers (the trace's normal, turned by the matrix,
            // needs no round trip through three floats).
            from_world
                .transform_vector3a(normal)
                .normalize_or_zero()
                .into(),
            distance,
        ),
        None => trace_miss(start, end),
    }
}

/// A trace's outputs (hit, point, normal, distance; rig space) for a miss of the trace from
/// `start` to `end`: the end, `+Z` and the whole length.
#[inline(always)]
pub(crate) fn trace_miss(start: Vec3, end: Vec3) -> (bool, Vec3, Vec3, f32) {
    (false, end, Vec3::Z, start.distance(end))
}

/// A two-bone IK's local axes (primary, secondary) as bits: equal keys are the same axes,
/// bit for bit, so [`BoneAxes::new`] of one serves the other.
#[inline(always)]
pub(crate) fn axes_key(primary: Vec3, secondary: Vec3) -> [[u32; 3]; 2] {
    // Written out: `array::map` leaves calls behind in the batch's IK.
    let bits = |v: Vec3| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
    [bits(primary), bits(secondary)]
}

/// The bone axes of a two-bone IK instruction's last solve, kept while it runs for a
/// batch's members: the next member with the same axes, bit for bit (a crowd's legs, whose
/// axes are the graph's constants), solves with them instead of preparing its own.
#[derive(Default)]
struct PreparedAxes(Option<([[u32; 3]; 2], BoneAxes)>);

impl PreparedAxes {
    /// [`BoneAxes::new`] of `primary` and `secondary` (local bone axes).
    #[inline(always)]
    fn get(&mut self, primary: Vec3, secondary: Vec3) -> &BoneAxes {
        let key = axes_key(primary, secondary);
        if self.0.as_ref().is_some_and(|(kept, _)| *kept != key) {
            self.0 = None;
        }
        &self
            .0
            .get_or_insert_with(|| (key, BoneAxes::new(primary, secondary)))
            .1
    }
}

/// The "next instruction" of an `End`: the event is over.
pub(crate) const END: usize = usize::MAX;

/// The base pointers of an instance's scalar slot arrays. Valid for a whole run of an event:
/// nothing resizes the scalar arrays during a run (arrays of arrays may grow; they are
/// separate allocations).
#[derive(Clone, Copy)]
pub(crate) struct Bases {
    pub(crate) bools: *mut bool,
    pub(crate) ints: *mut i32,
    pub(crate) floats: *mut f32,
    pub(crate) vec3s: *mut Vec3,
    pub(crate) quats: *mut Quat,
    pub(crate) transforms: *mut Transform,
}

impl Bases {
    /// No arrays (a batch's unused members).
    const NONE: Self = Self {
        bools: std::ptr::null_mut(),
        ints: std::ptr::null_mut(),
        floats: std::ptr::null_mut(),
        vec3s: std::ptr::null_mut(),
        quats: std::ptr::null_mut(),
        transforms: std::ptr::null_mut(),
    };

    /// Member `m`'s lane, from member 0's bases of [`Lanes`]: each pointer `m` items on.
    fn lane(self, m: usize) -> Self {
        Self {
            bools: self.bools.wrapping_add(m),
            ints: self.ints.wrapping_add(m),
            floats: self.floats.wrapping_add(m),
            vec3s: self.vec3s.wrapping_add(m),
            quats: self.quats.wrapping_add(m),
            transforms: self.transforms.wrapping_add(m),
        }
    }

    fn of(s: &mut Slots) -> Self {
        Self {
            bools: s.bools.as_mut_ptr(),
            ints: s.ints.as_mut_ptr(),
            floats: s.floats.as_mut_ptr(),
            vec3s: s.vec3s.as_mut_ptr(),
            quats: s.quats.as_mut_ptr(),
            transforms: s.transforms.as_mut_ptr(),
        }
    }
}

/// Every op's handler, as one `match` over `$op` with operands `$o` on slots `$s` (`$cx.slots`,
/// borrowed apart so the interpreter can hold it across instructions), whose scalar slot `k`
/// of each type is at `$bases` ([`Bases`]) + `k * $stride` (1 for an instance's own arrays,
/// [`BATCH`] for a batch member's lane of [`Lanes`]), and context `$cx`.
///
/// Each arm's body is handed to `$each!`, which runs it for every instance the expansion
/// site works on, binding `$s`, `$bases` and `$cx` to that instance's: [`once`] for a
/// single instance, a loop over a batch's members in [`run_batch`]. The `match` itself runs
/// once per instruction either way.
///
/// Expanded three times: in the interpreter loop ([`run_loop`]), in the batch loop
/// ([`run_batch`]) and in [`step`], the entry point of code generated ahead of time. After
/// a control op the expansion site decides what happens: `$jump!(target)` continues at
/// instruction `target`, `$end!()` ends the event. Before an op writes an array variable
/// (`ArraySetAt`, `ArrayAdd`, `ArrayReset` and `FindBones` once for all the instances, a
/// `Copy` or `Select` into it for each) `$forget!(elem, array)` is told: [`keep`] where nothing
/// holds copies of arrays, the batch's copies in [`run_batch`] (`crate::array_lanes`).
macro_rules! execute {
    ($op:expr, $o:expr, $s:ident, $bases:ident, $stride:expr, $cx:ident, $jump:ident, $end:ident, $each:ident, $forget:ident) => {{
        let (op, o): (Op, &[u32]) = ($op, $o);
        macro_rules! at {
            ($k:expr) => {
                o[$k] as usize
            };
        }
        // A scalar slot as a place: operand `$k` indexes scalar array `$a` through its base
        // pointer, without a bounds check.
        macro_rules! slot {
            ($a:ident, $k:expr) => {{
                let index = at!($k);
                debug_assert!(index < $s.$a.len(), "{op:?} operand {} out of bounds", $k);
                // SAFETY: in bounds by the module's invariant (the program's layout check
                // and the per-run length check), and the base pointer is current (see
                // `Bases`); the reference lives for one read or write.
                unsafe { &mut *$bases.$a.add(index * $stride) }
            }};
        }
        // A scalar slot of an element type named by `by_elem!` (bones are not behind base
        // pointers: they are indexed with a check).
        macro_rules! scalar {
            (bones, $k:expr) => {
                $s.bones[at!($k)]
            };
            ($a:ident, $k:expr) => {
                *slot!($a, $k)
            };
        }
        macro_rules! f {
            ($k:expr) => {
                *slot!(floats, $k)
            };
        }
        macro_rules! i {
            ($k:expr) => {
                *slot!(ints, $k)
            };
        }
        macro_rules! b {
            ($k:expr) => {
                *slot!(bools, $k)
            };
        }
        macro_rules! v {
            ($k:expr) => {
                *slot!(vec3s, $k)
            };
        }
        macro_rules! q {
            ($k:expr) => {
                *slot!(quats, $k)
            };
        }
        macro_rules! t {
            ($k:expr) => {
                *slot!(transforms, $k)
            };
        }
        // Bodies an op shares with the fused ops that run it: `$b` is the op's first
        // operand within the instruction's operands.
        macro_rules! arith {
            (AddF, $b:expr) => { f!($b + 2) = f!($b) + f!($b + 1) };
            (SubF, $b:expr) => { f!($b + 2) = f!($b) - f!($b + 1) };
            (MulF, $b:expr) => { f!($b + 2) = f!($b) * f!($b + 1) };
            (DivF, $b:expr) => { f!($b + 2) = k::div_f(f!($b), f!($b + 1)) };
            (AddV, $b:expr) => { v!($b + 2) = v!($b) + v!($b + 1) };
            (SubV, $b:expr) => { v!($b + 2) = v!($b) - v!($b + 1) };
            (ScaleV, $b:expr) => { v!($b + 2) = v!($b) * f!($b + 1) };
        }
        macro_rules! break_transform {
            ($b:expr) => {{
                let x = t!($b);
                v!($b + 1) = x.translation;
                q!($b + 2) = x.rotation;
                v!($b + 3) = x.scale;
            }};
        }
        macro_rules! get_transform {
            ($b:expr) => {{
                t!($b + 3) = bone_transform($cx.pose, $s.bones[at!($b)], i!($b + 1), b!($b + 2));
            }};
        }
        macro_rules! array_at {
            ($e:expr, $b:expr) => {{
                let index = i!($b + 1);
                macro_rules! get {
                    ($sc:ident, $ar:expr, $zero:expr) => {{
                        scalar!($sc, $b + 2) = array_get(&$ar[at!($b)], index, &$zero);
                    }};
                }
                by_elem!($e, $s, get);
            }};
        }
        // Copies the slot of operand `$from` into the slot of operand `$to` (type `$ty`).
        macro_rules! copy_slot {
            ($ty:expr, $from:expr, $to:expr) => {{
                let (from_k, to_k): (usize, usize) = ($from, $to);
                match $ty {
                    ValueType::Bool => b!(to_k) = b!(from_k),
                    ValueType::Int => i!(to_k) = i!(from_k),
                    ValueType::Float => f!(to_k) = f!(from_k),
                    ValueType::Vec3 => v!(to_k) = v!(from_k),
                    ValueType::Quat => q!(to_k) = q!(from_k),
                    ValueType::Transform => t!(to_k) = t!(from_k),
                    ValueType::Bone => $s.bones[at!(to_k)] = $s.bones[at!(from_k)],
                    ValueType::Name => $s.names[at!(to_k)] = $s.names[at!(from_k)],
                    ValueType::Array(e) => {
                        let (from, to) = (at!(from_k), at!(to_k));
                        $forget!(e, to as u32);
                        macro_rules! copy {
                            ($sc:ident, $ar:expr, $zero:expr) => {
                                copy_vec(&mut $ar, from, to)
                            };
                        }
                        by_elem!(e, $s, copy);
                    }
                }
            }};
        }
        match op {
            Op::End => $each!($end!()),
            Op::Jump => $each!($jump!(o[0] as usize)),
            Op::JumpIfFalse => $each!({
                if !b!(0) {
                    $jump!(o[1] as usize);
                }
            }),
            Op::ForEachNext(e) => with_elem!(e, E => $each!({
                let counter = i!(1);
                macro_rules! next {
                    ($sc:ident, $ar:expr, $zero:expr) => {{
                        let len = $ar[at!(0)].len();
                        if counter < 0 || counter as usize >= len {
                            $jump!(o[5] as usize);
                        } else {
                            scalar!($sc, 2) = $ar[at!(0)][counter as usize];
                            i!(3) = counter;
                            i!(4) = len as i32;
                            i!(1) = counter + 1;
                        }
                    }};
                }
                by_elem!(E, $s, next);
            })),
            Op::ForNext => $each!({
                let counter = i!(0);
                if counter >= i!(1) {
                    $jump!(o[3] as usize);
                } else {
                    i!(2) = counter;
                    i!(0) = counter + 1;
                }
            }),
            Op::Copy(ty) => $each!(copy_slot!(ty, 0, 1)),
            Op::IntToFloat | Op::ToFloat => $each!(f!(1) = i!(0) as f32),

            Op::AddF => $each!(arith!(AddF, 0)),
            Op::SubF => $each!(arith!(SubF, 0)),
            Op::MulF => $each!(arith!(MulF, 0)),
            Op::DivF => $each!(arith!(DivF, 0)),
            Op::MinF => $each!(f!(2) = f!(0).min(f!(1))),
            Op::MaxF => $each!(f!(2) = f!(0).max(f!(1))),
            Op::AbsF => $each!(f!(1) = f!(0).abs()),
            Op::NegF => $each!(f!(1) = -f!(0)),
            Op::ClampF => $each!(f!(3) = k::clamp_f(f!(0), f!(1), f!(2))),
            Op::SinF => $each!(f!(1) = k::sin_deg(f!(0))),
            Op::CosF => $each!(f!(1) = k::cos_deg(f!(0))),
            Op::TanF => $each!(f!(1) = k::tan_deg(f!(0))),
            Op::Atan2F => $each!(f!(2) = k::atan2_deg(f!(0), f!(1))),
            Op::SqrtF => $each!(f!(1) = k::sqrt(f!(0))),
            Op::PowF => $each!(f!(2) = f!(0).powf(f!(1))),
            Op::FmodF => $each!(f!(2) = k::mod_f(f!(0), f!(1))),
            Op::FractF => $each!(f!(1) = k::fract(f!(0))),
            Op::FloorF => $each!(f!(1) = f!(0).floor()),
            Op::CeilF => $each!(f!(1) = f!(0).ceil()),
            Op::RoundF => $each!(f!(1) = f!(0).round()),
            Op::LerpF => $each!(f!(3) = f!(0) + (f!(1) - f!(0)) * f!(2)),
            Op::RemapF => $each!(f!(6) = k::remap(f!(0), f!(1), f!(2), f!(3), f!(4), b!(5))),
            Op::SmoothStepF => $each!(f!(3) = k::smooth_step(f!(0), f!(1), f!(2))),
            Op::ToInt => $each!(i!(1) = k::to_int(f!(0))),

            Op::AddI => $each!(i!(2) = i!(0).wrapping_add(i!(1))),
            Op::SubI => $each!(i!(2) = i!(0).wrapping_sub(i!(1))),
            Op::MulI => $each!(i!(2) = i!(0).wrapping_mul(i!(1))),
            Op::DivI => $each!(i!(2) = k::div_i(i!(0), i!(1))),
            Op::ModI => $each!(i!(2) = k::mod_i(i!(0), i!(1))),
            Op::MinI => $each!(i!(2) = i!(0).min(i!(1))),
            Op::MaxI => $each!(i!(2) = i!(0).max(i!(1))),
            Op::AbsI => $each!(i!(1) = i!(0).wrapping_abs()),
            Op::NegI => $each!(i!(1) = i!(0).wrapping_neg()),
            Op::ClampI => $each!(i!(3) = i!(0).max(i!(1)).min(i!(2))),

            Op::And => $each!(b!(2) = b!(0) && b!(1)),
            Op::Or => $each!(b!(2) = b!(0) || b!(1)),
            Op::Xor => $each!(b!(2) = b!(0) != b!(1)),
            Op::Not => $each!(b!(1) = !b!(0)),
            Op::Equals(e) | Op::NotEquals(e) => $each!({
                let eq = match e {
                    Elem::Float => f!(0) == f!(1),
                    Elem::Int => i!(0) == i!(1),
                    Elem::Bool => b!(0) == b!(1),
                    Elem::Bone => $s.bones[at!(0)] == $s.bones[at!(1)],
                    Elem::Vec3 => v!(0) == v!(1),
                    Elem::Quat => q!(0) == q!(1),
                    Elem::Transform => t!(0) == t!(1),
                };
                b!(2) = eq == matches!(op, Op::Equals(_));
            }),
            Op::LessF => $each!(b!(2) = f!(0) < f!(1)),
            Op::LessEqualF => $each!(b!(2) = f!(0) <= f!(1)),
            Op::GreaterF => $each!(b!(2) = f!(0) > f!(1)),
            Op::GreaterEqualF => $each!(b!(2) = f!(0) >= f!(1)),
            Op::LessI => $each!(b!(2) = i!(0) < i!(1)),
            Op::LessEqualI => $each!(b!(2) = i!(0) <= i!(1)),
            Op::GreaterI => $each!(b!(2) = i!(0) > i!(1)),
            Op::GreaterEqualI => $each!(b!(2) = i!(0) >= i!(1)),
            Op::Select(ty) => $each!(copy_slot!(ty, if b!(0) { 1 } else { 2 }, 3)),

            Op::AddV => $each!(arith!(AddV, 0)),
            Op::SubV => $each!(arith!(SubV, 0)),
            Op::MulV => $each!(v!(2) = v!(0) * v!(1)),
            Op::DivV => $each!(v!(2) = k::div_v(v!(0), v!(1))),
            Op::ScaleV => $each!(arith!(ScaleV, 0)),
            Op::NegV => $each!(v!(1) = -v!(0)),
            Op::MinV => $each!(v!(2) = v!(0).min(v!(1))),
            Op::MaxV => $each!(v!(2) = v!(0).max(v!(1))),
            Op::AbsV => $each!(v!(1) = v!(0).abs()),
            Op::ClampV => $each!(v!(3) = v!(0).max(v!(1)).min(v!(2))),
            Op::LerpV => $each!(v!(3) = v!(0).lerp(v!(1), f!(2))),
            Op::LengthV => $each!(f!(1) = v!(0).length()),
            Op::DistanceV => $each!(f!(2) = v!(0).distance(v!(1))),
            Op::UnitV => $each!(v!(1) = k::unit_v(v!(0))),
            Op::DotV => $each!(f!(2) = v!(0).dot(v!(1))),
            Op::CrossV => $each!(v!(2) = v!(0).cross(v!(1))),
            Op::MakeVector => $each!(v!(3) = Vec3::new(f!(0), f!(1), f!(2))),
            Op::BreakVector => $each!({
                let x = v!(0);
                f!(1) = x.x;
                f!(2) = x.y;
                f!(3) = x.z;
            }),

            Op::QuatFromAxisAngle => $each!(q!(2) = k::quat_from_axis_angle(v!(0), f!(1))),
            Op::QuatFromEuler => $each!({
                q!(2) = strider_core::euler::quat_from_euler(v!(0), k::euler_order(i!(1)));
            }),
            Op::EulerFromQuat => $each!({
                v!(2) = strider_core::euler::euler_from_quat(q!(0), k::euler_order(i!(1)));
            }),
            Op::MulQ => $each!(q!(2) = k::unit_q(q!(0) * q!(1))),
            Op::InverseQ => $each!(q!(1) = k::unit_q(q!(0)).inverse()),
            Op::UnitQ => $each!(q!(1) = k::unit_q(q!(0))),
            Op::SlerpQ => $each!(q!(3) = k::slerp(q!(0), q!(1), f!(2))),
            Op::RotateVector => $each!(v!(2) = k::rotate_vector(q!(0), v!(1))),
            Op::QuatScale => $each!(q!(2) = k::quat_scale(q!(0), f!(1))),
            Op::FindQuatBetween => $each!(q!(2) = k::find_quat_between(v!(0), v!(1))),

            Op::MakeTransform => $each!(t!(3) = Transform::new(v!(0), k::unit_q(q!(1)), v!(2))),
            Op::BreakTransform => $each!(break_transform!(0)),
            Op::MulT => $each!(t!(2) = t!(0) * t!(1)),
            Op::InverseT => $each!(t!(1) = t!(0).inverse()),
            Op::MakeRelative => $each!(t!(2) = t!(0).relative_to(&t!(1))),
            Op::MakeAbsolute => $each!(t!(2) = t!(1) * t!(0)),
            Op::TransformPoint => $each!(v!(2) = t!(0).transform_point(v!(1))),
            Op::TransformVector => $each!(v!(2) = t!(0).transform_vector(v!(1))),
            Op::RotateAroundPoint => $each!(t!(3) = k::rotate_around_point(t!(0), v!(1), q!(2))),
            Op::InterpolateTransform => $each!({
                let w = f!(2);
                t!(3) = if w.is_nan() {
                    t!(0)
                } else {
                    t!(0).interpolate(&t!(1), w)
                };
            }),
            Op::AimMath => $each!({
                let tr = t!(0);
                let target = v!(2);
                let direction = if i!(3) == 0 {
                    target
                } else {
                    target - tr.translation
                };
                t!(5) = k::aim(tr, v!(1), direction, f!(4));
            }),
            Op::AlignToNormal => $each!(t!(4) = k::aim(t!(0), v!(1), v!(2), f!(3))),
            Op::Spline => $each!({
                let mode = if i!(2) == 1 {
                    SplineMode::CatmullRom
                } else {
                    SplineMode::BSpline
                };
                let (p, t) = spline::evaluate(&$s.vec3_arrays[at!(0)], f!(1), mode);
                v!(3) = p;
                v!(4) = t;
            }),
            Op::ClampLength => $each!(v!(3) = k::clamp_length(v!(0), f!(1), f!(2))),
            Op::ClampSpatially => $each!(v!(4) = k::clamp_spatially(v!(0), v!(1), f!(2), f!(3))),

            Op::GetTransform => $each!(get_transform!(0)),
            Op::SetTransform => $each!({
                if let Some(bi) = bone($cx.pose, $s.bones[at!(0)]) {
                    set_transform($cx.pose, bi, t!(1), i!(2), b!(3), f!(4));
                }
            }),
            Op::GetParent => $each!($s.bones[at!(1)] = parent_of($cx.pose, $s.bones[at!(0)])),
            Op::FindBones => {
                $forget!(Elem::Bone, o[3]);
                $each!({
                    let out = &mut $s.bone_arrays[at!(3)];
                    match bone($cx.pose, $s.bones[at!(0)]) {
                        Some(root) => {
                            let contains = &$cx.texts[$s.names[at!(1)] as usize];
                            let excludes = &$cx.texts[$s.names[at!(2)] as usize];
                            k::find_bones($cx.pose.skeleton(), root, contains, excludes, out);
                        }
                        None => out.clear(),
                    }
                })
            }
            Op::TwoBoneIK => {
                let mut prepared = PreparedAxes::default();
                $each!({
                    let chain = (
                        bone($cx.pose, $s.bones[at!(0)]),
                        bone($cx.pose, $s.bones[at!(1)]),
                        bone($cx.pose, $s.bones[at!(2)]),
                    );
                    let (reached, distance) = match chain {
                        (Some(a), Some(b), Some(c)) => {
                            let pole = if i!(7) == 1 {
                                Pole::Location(v!(6))
                            } else {
                                Pole::Direction(v!(6))
                            };
                            let (primary_axis, secondary_axis) = (v!(4), v!(5));
                            let axes = prepared.get(primary_axis, secondary_axis);
                            let ik = TwoBoneIk {
                                primary_axis,
                                secondary_axis,
                                pole,
                                weight: f!(8),
                                stretch: b!(9).then_some((f!(10), f!(11))),
                                set_effector_rotation: b!(12),
                            };
                            let report = ik.solve_with_axes(axes, $cx.pose, a, b, c, t!(3));
                            (report.reached, report.distance_to_target)
                        }
                        _ => (false, f32::INFINITY),
                    };
                    b!(13) = reached;
                    f!(14) = distance;
                })
            }
            Op::DeltaTime => $each!(f!(0) = $cx.dt),
            Op::WorldTransform => $each!(t!(0) = $cx.to_world),
            Op::LineTrace | Op::SphereTrace => $each!({
                let (start, end) = (v!(0), v!(1));
                // Each answer's vectors read in place, as the world stored them (see
                // `load_vec3` and `read_hit`).
                let (hit, outs) = if op == Op::LineTrace {
                    let q = trace_ends(&$cx.to_world_matrix, start, end);
                    (read_hit(&$cx.world.line_trace(q.start, q.end)), 2)
                } else {
                    let q = trace_query(&$cx.to_world_matrix, start, end, f!(2));
                    (read_hit(&$cx.world.sphere_trace(q.start, q.end, q.radius)), 3)
                };
                let (hit, point, normal, distance) =
                    trace_outputs(hit, start, end, &$cx.from_world_matrix);
                (b!(outs), v!(outs + 1), v!(outs + 2), f!(outs + 3)) =
                    (hit, point, normal, distance);
            }),

            Op::FloatLerp => $each!(f!(3) = loco::lerp_exponential(f!(0), f!(1), $cx.dt, f!(2))),
            Op::VectorLerp => $each!({
                let max = f!(3);
                v!(4) = if max > 0.0 {
                    loco::lerp_max_step(v!(0), v!(1), $cx.dt, f!(2), max)
                } else {
                    loco::lerp_exponential_v(v!(0), v!(1), $cx.dt, f!(2))
                };
            }),
            Op::QuatLerp => $each!(q!(3) = loco::lerp_exponential_q(q!(0), q!(1), $cx.dt, f!(2))),
            Op::FInterpToF => $each!(f!(3) = loco::finterp_to(f!(0), f!(1), $cx.dt, f!(2))),
            Op::FInterpToV => $each!(v!(3) = loco::vinterp_to(v!(0), v!(1), $cx.dt, f!(2))),
            Op::FInterpToQ => $each!(q!(3) = loco::qinterp_to(q!(0), q!(1), $cx.dt, f!(2))),
            Op::SpringF => $each!({
                // State: [last run, value, velocity]. Advances once per run, however many
                // steps read it; starts at rest on the first target it sees.
                if i!(3) != $cx.run {
                    let target = f!(0);
                    if i!(3) == 0 {
                        f!(4) = target;
                        f!(5) = 0.0;
                    }
                    i!(3) = $cx.run;
                    let (x, vel) = loco::spring_damper(f!(4), f!(5), target, f!(1), $cx.dt);
                    f!(4) = x;
                    f!(5) = vel;
                }
                f!(2) = f!(4);
            }),
            Op::SpringV => $each!({
                if i!(3) != $cx.run {
                    let target = v!(0);
                    if i!(3) == 0 {
                        v!(4) = target;
                        v!(5) = Vec3::ZERO;
                    }
                    i!(3) = $cx.run;
                    let (x, vel) = loco::spring_damper_v(v!(4), v!(5), target, f!(1), $cx.dt);
                    v!(4) = x;
                    v!(5) = vel;
                }
                v!(2) = v!(4);
            }),
            Op::MovementAngleOffset => $each!({
                f!(8) = loco::get_movement_angle_offset(
                    v!(0),
                    f!(1),
                    f!(2),
                    $cx.dt,
                    f!(3),
                    f!(4),
                    f!(5),
                    f!(6),
                    f!(7),
                );
            }),
            Op::PerFootRotationFactor => $each!({
                f!(3) = loco::per_foot_rotation_factor(f!(0), f!(1), f!(2))
            }),
            Op::LimitRotationAroundZ => $each!(q!(3) = loco::limit_rotation_around_z(q!(0), f!(1), f!(2))),
            Op::FootAvoidance => $each!(v!(5) = loco::foot_avoidance(v!(0), v!(1), f!(2), b!(3), f!(4))),
            Op::KneeVector => $each!(v!(5) = loco::knee_vector(q!(0), q!(1), v!(2), f!(3), f!(4))),
            Op::ArmSwingRotation => $each!({
                f!(13) = loco::arm_swing_pitch(
                    f!(0),
                    v!(1),
                    q!(2),
                    f!(3),
                    f!(4),
                    f!(5),
                    f!(6),
                    f!(7),
                    f!(8),
                    f!(9),
                    f!(10),
                    f!(11),
                    f!(12),
                );
            }),
            Op::ClavicleOffset => $each!(f!(4) = loco::clavicle_offset(f!(0), f!(1), f!(2), f!(3))),
            Op::PelvisLean => $each!({
                let (pitch, shift) = loco::pelvis_lean(v!(0), f!(1), f!(2), f!(3));
                f!(4) = pitch;
                f!(5) = shift;
            }),
            Op::PelvisSideLean => $each!(f!(3) = loco::pelvis_side_lean(f!(0), f!(1), f!(2))),
            Op::FootPivots => $each!({
                let (ball, tip, heel) = loco::foot_pivots(v!(0), v!(1), f!(2), f!(3), f!(4), f!(5));
                v!(6) = ball;
                v!(7) = tip;
                v!(8) = heel;
            }),
            Op::CycleStep => $each!({
                let (master, per_foot) = loco::cycle_step(f!(0), $cx.dt, f!(1), f!(2), b!(3));
                f!(4) = master;
                f!(5) = per_foot;
            }),
            Op::FootOffsetFromTrace => $each!(f!(3) = loco::foot_offset_from_trace(b!(0), f!(1), f!(2))),
            Op::RotationFromNormal => $each!({
                let n = v!(0);
                let (pitch, roll) = loco::rotation_from_normal(n);
                f!(1) = pitch;
                f!(2) = roll;
                q!(3) = loco::rotation_from_normal_quat(n);
            }),

            Op::ArrayAt(e) => with_elem!(e, E => $each!(array_at!(E, 0))),
            Op::MulFMulF => $each!({
                arith!(MulF, 0);
                arith!(MulF, 3);
            }),
            Op::SubFMulF => $each!({
                arith!(SubF, 0);
                arith!(MulF, 3);
            }),
            Op::MulFAddF => $each!({
                arith!(MulF, 0);
                arith!(AddF, 3);
            }),
            Op::SubFAddF => $each!({
                arith!(SubF, 0);
                arith!(AddF, 3);
            }),
            Op::AddFMulF => $each!({
                arith!(AddF, 0);
                arith!(MulF, 3);
            }),
            Op::MulFSubF => $each!({
                arith!(MulF, 0);
                arith!(SubF, 3);
            }),
            Op::AddFAddF => $each!({
                arith!(AddF, 0);
                arith!(AddF, 3);
            }),
            Op::DivFSubF => $each!({
                arith!(DivF, 0);
                arith!(SubF, 3);
            }),
            Op::AddVAddV => $each!({
                arith!(AddV, 0);
                arith!(AddV, 3);
            }),
            Op::AddVSubV => $each!({
                arith!(AddV, 0);
                arith!(SubV, 3);
            }),
            Op::MulFScaleV => $each!({
                arith!(MulF, 0);
                arith!(ScaleV, 3);
            }),
            Op::DivFScaleV => $each!({
                arith!(DivF, 0);
                arith!(ScaleV, 3);
            }),
            Op::GetTransformBreakTransform => $each!({
                get_transform!(0);
                break_transform!(4);
            }),
            Op::ArrayAtBreakTransform => $each!({
                array_at!(Elem::Transform, 0);
                break_transform!(3);
            }),
            Op::ArrayCount(e) => $each!({
                macro_rules! count {
                    ($sc:ident, $ar:expr, $zero:expr) => {
                        i!(1) = $ar[at!(0)].len() as i32
                    };
                }
                by_elem!(e, $s, count);
            }),
            Op::ArraySetAt(e) => {
                $forget!(e, o[0]);
                $each!({
                    let index = i!(1);
                    macro_rules! set {
                        ($sc:ident, $ar:expr, $zero:expr) => {{
                            let value = scalar!($sc, 2);
                            array_set(&mut $ar[at!(0)], index, value);
                        }};
                    }
                    by_elem!(e, $s, set);
                })
            }
            Op::ArrayAdd(e) => {
                $forget!(e, o[0]);
                $each!({
                    macro_rules! add {
                        ($sc:ident, $ar:expr, $zero:expr) => {{
                            let value = scalar!($sc, 1);
                            $ar[at!(0)].push(value);
                        }};
                    }
                    by_elem!(e, $s, add);
                })
            }
            Op::ArrayReset(e) => {
                $forget!(e, o[0]);
                $each!({
                    macro_rules! reset {
                        ($sc:ident, $ar:expr, $zero:expr) => {
                            $ar[at!(0)].clear()
                        };
                    }
                    by_elem!(e, $s, reset);
                })
            }

            // Draw ops: DebugDraw::push records nothing when drawing is off.
            Op::DrawPoint => $each!({
                $cx.debug.push(DebugPrimitive::Point {
                    position: v!(0),
                    size: f!(1),
                    color: color(v!(2)),
                });
            }),
            Op::DrawLine => $each!({
                $cx.debug.push(DebugPrimitive::Line {
                    start: v!(0),
                    end: v!(1),
                    thickness: f!(2),
                    color: color(v!(3)),
                });
            }),
            Op::DrawArrow => $each!({
                $cx.debug.push(DebugPrimitive::Arrow {
                    start: v!(0),
                    end: v!(1),
                    thickness: f!(2),
                    color: color(v!(3)),
                });
            }),
            Op::DrawSphere => $each!({
                $cx.debug.push(DebugPrimitive::Sphere {
                    center: v!(0),
                    radius: f!(1),
                    color: color(v!(2)),
                });
            }),
            Op::DrawBox => $each!({
                $cx.debug.push(DebugPrimitive::Box {
                    transform: t!(0),
                    half_extents: v!(1),
                    color: color(v!(2)),
                });
            }),
            Op::DrawSpline => $each!({
                if $cx.debug.is_enabled() {
                    let mode = if i!(1) == 1 {
                        SplineMode::CatmullRom
                    } else {
                        SplineMode::BSpline
                    };
                    let pieces = i!(2).clamp(1, 256);
                    let points = &$s.vec3_arrays[at!(0)];
                    let (thickness, c) = (f!(3), color(v!(4)));
                    let mut start = spline::evaluate(points, 0.0, mode).0;
                    for k in 1..=pieces {
                        let end = spline::evaluate(points, k as f32 / pieces as f32, mode).0;
                        $cx.debug.push(DebugPrimitive::Line {
                            start,
                            end,
                            thickness,
                            color: c,
                        });
                        start = end;
                    }
                }
            }),
            Op::DrawTransform => $each!({
                $cx.debug.push(DebugPrimitive::Axes {
                    transform: t!(0),
                    size: f!(1),
                    thickness: f!(2),
                });
            }),
        }
    }};
}

/// Runs from `entry` until an `End` instruction.
pub(crate) fn run(program: &Program, entry: u32, cx: &mut Ctx<'_>) {
    // Profiling picks a separately compiled copy of the loop once per run, so the copy that
    // runs unprofiled has no per-instruction test; without the feature there is no timing
    // code at all.
    #[cfg(feature = "profile")]
    if let Some(profile) = cx.profile.take() {
        run_loop::<true>(program, entry, cx, profile);
        return;
    }
    run_loop::<false>(program, entry, cx, &mut []);
}

/// The executor loop. With `PROFILE` (only instantiated with the `profile` feature), adds
/// each instruction's elapsed time and one run to `profile[pc]`.
#[cfg_attr(not(feature = "profile"), allow(unused_variables))]
fn run_loop<const PROFILE: bool>(
    program: &Program,
    entry: u32,
    cx: &mut Ctx<'_>,
    profile: &mut [crate::profile::InstrProfile],
) {
    let code: &[Instr] = &program.code;
    let operands: &[u32] = &program.operands;
    let s = &mut *cx.slots;
    // Taken once for the whole run, so the loop keeps them in registers or on its stack:
    // the handlers' writes through them cannot be told apart from writes to `Slots`.
    let bases = Bases::of(s);
    let mut pc = entry as usize;
    // One clock read per instruction: an instruction's time runs from the end of the one
    // before it to its own end.
    #[cfg(feature = "profile")]
    let mut last = PROFILE.then(std::time::Instant::now);
    let mut path = 0u64;
    let mut taken = 0u64;
    loop {
        #[cfg(feature = "profile")]
        let here = pc;
        // SAFETY: `pc` is an instruction: the entry and every jump target are (checked by
        // `ProgramBuilder::finish`), and the last instruction cannot fall through.
        let Instr { op, args } = unsafe { *code.get_unchecked(pc) };
        pc += 1;
        macro_rules! jump {
            ($target:expr) => {{
                // The jump is from the instruction before `pc`.
                path = next_path(path, pc - 1);
                taken |= site_bit(pc - 1);
                pc = $target;
            }};
        }
        macro_rules! end {
            () => {{
                #[cfg(feature = "profile")]
                if PROFILE {
                    // `End` counts as run but takes no time of its own.
                    profile[here].count += 1;
                }
                cx.path = path;
                cx.taken = taken;
                return;
            }};
        }
        // A window of constant length: the operand list is padded at its end by
        // `MAX_OPERANDS`, past every instruction's first operand.
        let args = args as usize;
        debug_assert!(args + MAX_OPERANDS <= operands.len());
        execute!(
            op,
            // SAFETY: in bounds by the padding (above).
            unsafe { operands.get_unchecked(args..args + MAX_OPERANDS) },
            s,
            bases,
            1,
            cx,
            jump,
            end,
            once,
            keep
        );
        #[cfg(feature = "profile")]
        if PROFILE && let Some(started) = last {
            let now = std::time::Instant::now();
            let entry = &mut profile[here];
            entry.nanos += now.duration_since(started).as_nanos() as u64;
            entry.count += 1;
            last = Some(now);
        }
    }
}

/// The most instances one batch of [`crate::Instance::run_forward_batch`] runs together
/// through each instruction.
pub const BATCH: usize = 16;

/// Runs from `entry` until an `End` instruction on every member of a batch, dispatching each
/// instruction once for all the members that are at it: their handlers run one after the
/// other, in member order, on each member's own slots, pose and context.
///
/// Members that branch apart continue separately: the members at the lowest instruction run
/// next (`group`), the others wait at theirs until the group reaches them (forward jumps over
/// an `if`'s other side, and past a loop a member left early, meet again). Every member runs
/// exactly the instructions it would run alone, in the same order, so its results are
/// bit-identical to [`run`]'s; only the interleaving between members differs, and members
/// share nothing they write.
///
/// For a program with at least two instructions per scalar slot ([`lanes_pay_off`]), the
/// members' scalar slots are worked on in this thread's lanes ([`crate::lanes`]): copied
/// in first and back when every member has ended, as `copies` says (see [`Copies`]: the
/// slots of values that live only within a run go neither way unless `copies.kept` covers
/// them); smaller programs run on each member's own slots. While the whole batch is at
/// one instruction, a plain scalar op runs on all lanes at once ([`crate::lanes::run_wide`])
/// and a jump that every member takes, or none, moves the batch without visiting its members.
///
/// `code` and `operands` are the program's, passed apart so that the compiler knows that the
/// handlers' writes do not touch them (operand fetches can stay out of the member loop).
/// Returns the number of instructions dispatched (each once for all the members at it) in
/// the crate's own test builds, for the executor's tests; 0 in every other build, whose
/// loop does not count (an add at every dispatch, which the frame does not need).
// Each handler body is expanded once per op with `each!`; bodies that read no slots (or
// no scalar slots) leave that iteration's `s` or `b` unread.
#[allow(unused_assignments)]
pub(crate) fn run_batch(
    code: &[Instr],
    operands: &[u32],
    entry: u32,
    copies: Copies<'_>,
    members: &mut [Ctx<'_>],
) -> usize {
    let n = members.len();
    assert!(n <= BATCH, "a batch has at most {BATCH} members");
    if n == 0 {
        return 0;
    }
    // A batch whose members profile (the caller batches only members that all do, or all
    // do not) runs a separately compiled copy of the loop that times each dispatch, so
    // the copy that runs unprofiled has no per-dispatch test; without the feature there
    // is no timing code at all.
    #[cfg(feature = "profile")]
    let profiled = members[0].profile.is_some();
    #[cfg(feature = "profile")]
    debug_assert!(
        members.iter().all(|cx| cx.profile.is_some() == profiled),
        "a batch's members all profile, or none does"
    );
    if !lanes_pay_off(code.len(), copies.lens) {
        // No lanes: the empty scratch is never loaded.
        let mut none = Lanes::default();
        #[cfg(feature = "profile")]
        if profiled {
            return run_group::<false, true>(code, operands, entry, copies, members, &mut none);
        }
        return run_group::<false, false>(code, operands, entry, copies, members, &mut none);
    }
    LANES.with(|cell| {
        // A batch run from inside another one on this thread (a world query that runs a
        // rig of its own) gets lanes of its own, allocated for this run.
        let (mut thread_lanes, mut own) = (cell.try_borrow_mut().ok(), None);
        let lanes = match thread_lanes.as_deref_mut() {
            Some(lanes) => lanes,
            None => own.insert(Lanes::default()),
        };
        #[cfg(feature = "profile")]
        if profiled {
            return run_group_lanes::<true>(code, operands, entry, copies, members, lanes);
        }
        run_group_lanes::<false>(code, operands, entry, copies, members, lanes)
    })
}

/// `run_group::<true, PROFILE>` on the machine code `batch_code()` picks (see
/// [`crate::batch_code`]).
fn run_group_lanes<const PROFILE: bool>(
    code: &[Instr],
    operands: &[u32],
    entry: u32,
    copies: Copies<'_>,
    members: &mut [Ctx<'_>],
    lanes: &mut Lanes,
) -> usize {
    #[cfg(target_arch = "x86_64")]
    if batch_code() == BatchCode::Avx2 {
        // SAFETY: the processor has AVX2 (`batch_code` checked it).
        return unsafe { run_group_avx2::<PROFILE>(code, operands, entry, copies, members, lanes) };
    }
    run_group::<true, PROFILE>(code, operands, entry, copies, members, lanes)
}

/// `run_group::<true, PROFILE>` compiled for AVX2: the same source (inlined here), wider
/// registers. Callers must make sure the processor has AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_group_avx2<const PROFILE: bool>(
    code: &[Instr],
    operands: &[u32],
    entry: u32,
    copies: Copies<'_>,
    members: &mut [Ctx<'_>],
    lanes: &mut Lanes,
) -> usize {
    run_group::<true, PROFILE>(code, operands, entry, copies, members, lanes)
}

/// Adds a dispatch's time, `nanos`, to the profile of each member in `group` (bit `m` for
/// member `m`) at instruction `pc`, shared equally (the remainder to the first), with one
/// run each: what each member would have spent at the instruction, run together.
#[cfg(feature = "profile")]
fn profile_dispatch(members: &mut [Ctx<'_>], group: u32, pc: usize, nanos: u64) {
    let n = u64::from(group.count_ones().max(1));
    let (share, mut rest) = (nanos / n, nanos % n);
    let mut left = group;
    while left != 0 {
        let m = left.trailing_zeros() as usize;
        left &= left - 1;
        if let Some(entry) = members[m]
            .profile
            .as_deref_mut()
            .and_then(|p| p.get_mut(pc))
        {
            entry.nanos += share + rest;
            entry.count += 1;
        }
        rest = 0;
    }
}

/// Grows the calling thread's scratch that [`run_batch`] keeps for a program of `code`
/// over scalar slots `lens`, with initial slots `initial`, to what its first batch on
/// this thread would grow it to: the lanes and the room for copies of its arrays, when
/// the program runs on them, and the IKs' chain lanes when it also has a
/// `TwoBoneIK`. Leaves the lanes alone while a batch runs on this thread (it holds them).
pub(crate) fn reserve_batch_scratch(code: &[Instr], lens: &ScalarLens, initial: &Slots) {
    if !lanes_pay_off(code.len(), lens) {
        return;
    }
    LANES.with(|cell| {
        if let Ok(mut lanes) = cell.try_borrow_mut() {
            lanes.reserve(lens);
            lanes.arrays.reserve(initial);
        }
    });
    if code.iter().any(|i| i.op == Op::TwoBoneIK) {
        crate::per_member::reserve_chain_lanes();
    }
}

/// Whether a program of `code_len` instructions over scalar slots `lens` runs its batches
/// on lanes: when it has at least two instructions per scalar slot. Copying a member's
/// slots into the lanes and back costs a few machine instructions per slot, which a
/// program of a few dozen instructions (`graphs/pelvis_bob.ron`: 17 over 20 slots) does
/// not win back; `graphs/locomotion.ron` has 1 712 over 350.
fn lanes_pay_off(code_len: usize, lens: &ScalarLens) -> bool {
    code_len >= 2 * lens.0.iter().sum::<usize>()
}

/// [`run_batch`], on `lanes` (`LANES`: the members' scalar slots are copied into them, run
/// there and copied back) or on each member's own slots. Always inlined, so that
/// [`run_group_avx2`] compiles the whole loop, wide ops and lane copies included, for AVX2.
/// With `PROFILE` (only instantiated with the `profile` feature, for members that all
/// profile), each dispatch's time, from its start to the next one's, is shared among the
/// members at it ([`profile_dispatch`]).
#[allow(unused_assignments)]
#[inline(always)]
fn run_group<const LANES: bool, const PROFILE: bool>(
    code: &[Instr],
    operands: &[u32],
    entry: u32,
    copies: Copies<'_>,
    members: &mut [Ctx<'_>],
    lanes: &mut Lanes,
) -> usize {
    let n = members.len();
    let mut dispatches = 0;
    // Without lanes, each member's own base pointers (stride 1).
    let mut own = [Bases::NONE; BATCH];
    if LANES {
        crate::prefetch::batch(members);
        lanes.load(copies, members);
    } else {
        for (b, cx) in own.iter_mut().zip(members.iter_mut()) {
            *b = Bases::of(cx.slots);
        }
    }
    // Member 0's lane; member `m`'s is `m` items on in every array.
    let lane0 = lanes.bases();
    let dts: [f32; BATCH] = std::array::from_fn(|m| members.get(m).map_or(0.0, |cx| cx.dt));
    // The world the whole batch traces, if it shares one (the traces ask it once).
    let world = if LANES {
        crate::per_member::shared_world(members)
    } else {
        None
    };
    // The members' matrices to and from world space, by entry, read at the batch's first
    // trace.
    let mut frames = crate::per_member::FrameColumns::new();
    // Whether any member records debug drawing: when none does, the batch passes the draw
    // ops by (their handlers record only, and only when enabled).
    let drawing = members.iter().any(|cx| cx.debug.is_enabled());
    // Where each member outside the group is (`END` once it has ended); the group's members
    // are all at `pc`.
    let mut pcs = [END; BATCH];
    // The members' path keys (`Ctx::path`) and jump sites (`Ctx::taken`) so far: all
    // `shared` and `shared_taken` until a member jumps on its own (`apart`), then each
    // member's in `paths` and `takens`. Two arrays rather than one of (key, sites) pairs:
    // a batch-wide jump then updates each as one loop over 16 words; one array of pairs
    // measured 2.8 % more instructions per walk_flat character-frame.
    let mut shared = 0u64;
    let mut apart = false;
    let mut paths = [0u64; BATCH];
    let mut shared_taken = 0u64;
    let mut takens = [0u64; BATCH];
    let mut pc = entry as usize;
    let everyone: u32 = (1u32 << n) - 1;
    let mut group = everyone;
    // The lowest instruction a member outside the group waits at (`END`: none waits).
    let mut waiting = END;
    // The member a handler runs for, its context, slots and slot bases (set by `each!`
    // below: a macro's own `let`s are invisible to the handler bodies it is given), and the
    // members whose instruction jumped or ended.
    let mut m: usize;
    let mut cx: &mut Ctx<'_>;
    let mut s: &mut Slots;
    let mut b: Bases;
    let mut moved: u32;
    // The dispatch being timed (instruction, members at it) and when it started.
    #[cfg(feature = "profile")]
    let mut timed: Option<(usize, u32, std::time::Instant)> = None;
    loop {
        #[cfg(feature = "profile")]
        if PROFILE {
            let now = std::time::Instant::now();
            if let Some((at, who, started)) = timed {
                // `End` counts as run but takes no time of its own, as in the loop alone.
                let nanos = if matches!(code[at].op, Op::End) {
                    0
                } else {
                    now.duration_since(started).as_nanos() as u64
                };
                profile_dispatch(members, who, at, nanos);
            }
            timed = Some((pc, group, now));
        }
        // Instruction `pc`'s op and operand window.
        let fetch = |pc: usize| {
            // SAFETY: as in `run_loop`.
            let Instr { op, args } = unsafe { *code.get_unchecked(pc) };
            let args = args as usize;
            debug_assert!(args + MAX_OPERANDS <= operands.len());
            // SAFETY: in bounds by the operand list's padding (see `run_loop`).
            (op, unsafe {
                operands.get_unchecked(args..args + MAX_OPERANDS)
            })
        };
        let (mut op, mut o) = fetch(pc);
        moved = 0;
        if cfg!(test) {
            // Counted for the tests only (see above).
            dispatches += 1;
        }
        if LANES && !PROFILE && group == everyone {
            // A run of plain scalar ops with the whole batch here: each runs on all lanes
            // and the next follows at once, through a jump table of its own (the dispatch
            // below tests for the jumps first).
            // SAFETY: an instruction of the program whose slots the lanes hold.
            while unsafe { crate::lanes::run_wide(op, o, lane0, n, &dts) } {
                pc += 1;
                (op, o) = fetch(pc);
                if cfg!(test) {
                    dispatches += 1;
                }
            }
        }
        // Runs `$body` for member `$k` (`< n`), with its context, slots and slot bases.
        macro_rules! visit {
            ($k:expr, $body:expr) => {{
                m = $k;
                // SAFETY: `m < n`.
                cx = unsafe { members.get_unchecked_mut(m) };
                s = &mut *cx.slots;
                b = if LANES {
                    lane0.lane(m)
                } else {
                    // SAFETY: `m < n <= BATCH`.
                    unsafe { *own.get_unchecked(m) }
                };
                $body;
            }};
        }
        macro_rules! each {
            ($body:expr) => {{
                if group == everyone {
                    // The common case, as a counted loop: its trip count and addresses are
                    // known before it starts.
                    for k in 0..n {
                        visit!(k, $body);
                    }
                } else {
                    // `group` has bits for members `0..n` only.
                    let mut rest = group;
                    while rest != 0 {
                        let k = rest.trailing_zeros() as usize;
                        rest &= rest - 1;
                        visit!(k, $body);
                    }
                }
            }};
        }
        // Where the first member that jumped went, and whether another went elsewhere.
        let mut common = END;
        let mut split = false;
        macro_rules! go {
            ($target:expr) => {{
                let target = $target;
                if moved == 0 {
                    common = target;
                } else if target != common {
                    split = true;
                }
                pcs[m] = target;
                moved |= 1 << m;
            }};
        }
        macro_rules! jump {
            ($target:expr) => {{
                if !apart {
                    paths = [shared; BATCH];
                    takens = [shared_taken; BATCH];
                    apart = true;
                }
                paths[m] = next_path(paths[m], pc);
                takens[m] |= site_bit(pc);
                go!($target)
            }};
        }
        macro_rules! end {
            () => {
                go!(END)
            };
        }
        if LANES && group == everyone {
            // The whole batch is here (so no member waits elsewhere): a jump that every
            // member takes, or none, moves the batch at once, and a plain scalar op runs
            // on all lanes together.
            // Every member jumps to `$target`: the jump goes into every member's path key and
            // jump sites.
            macro_rules! batch_jump {
                ($target:expr) => {{
                    if apart {
                        paths = paths.map(|p| next_path(p, pc));
                        takens = takens.map(|t| t | site_bit(pc));
                    } else {
                        shared = next_path(shared, pc);
                        shared_taken |= site_bit(pc);
                    }
                    pc = $target;
                    continue;
                }};
            }
            match op {
                Op::Jump => batch_jump!(o[0] as usize),
                Op::JumpIfFalse => {
                    // SAFETY: operand 0 is a bool slot (the op's layout).
                    match unsafe { crate::lanes::agree(lane0, o[0], n) } {
                        Some(true) => {
                            pc += 1;
                            continue;
                        }
                        Some(false) => batch_jump!(o[1] as usize),
                        None => {}
                    }
                }
                // SAFETY: an instruction of the program whose slots the lanes hold. (Run
                // by the loop above when not profiling.)
                _ if PROFILE && unsafe { crate::lanes::run_wide(op, o, lane0, n, &dts) } => {
                    pc += 1;
                    continue;
                }
                strider_nodes::draw_ops!() if !drawing => {
                    pc += 1;
                    continue;
                }
                // SAFETY: as above; `members` is the batch the lanes were loaded from.
                Op::ForEachNext(e) => {
                    match unsafe {
                        crate::per_member::for_each_next(e, o, &lane0, &mut lanes.arrays, members)
                    } {
                        Some(true) => {
                            pc += 1;
                            continue;
                        }
                        Some(false) => batch_jump!(o[5] as usize),
                        None => {}
                    }
                }
                // SAFETY: as above; `members` is the batch the lanes were loaded from.
                Op::SphereTrace
                    if unsafe {
                        crate::per_member::sphere_traces(o, lane0, world, &mut frames, members)
                    } =>
                {
                    pc += 1;
                    continue;
                }
                // SAFETY: as above.
                Op::LineTrace
                    if unsafe {
                        crate::per_member::line_traces(o, lane0, world, &mut frames, members)
                    } =>
                {
                    pc += 1;
                    continue;
                }
                // SAFETY: as above.
                Op::TwoBoneIK if unsafe { crate::per_member::two_bone_iks(o, &lane0, members) } => {
                    pc += 1;
                    continue;
                }
                // SAFETY: as above.
                _ if unsafe {
                    crate::per_member::run_per_member(op, o, &lane0, &mut lanes.arrays, members)
                } =>
                {
                    pc += 1;
                    continue;
                }
                _ => {}
            }
        }
        // A handler's write of an array variable: the batch's copy of it, if any, no longer
        // holds what the members' arrays will (`crate::array_lanes`).
        macro_rules! forget {
            ($elem:expr, $array:expr) => {
                if LANES {
                    lanes.arrays.forget($elem, $array)
                }
            };
        }
        execute!(
            op,
            o,
            s,
            b,
            if LANES { BATCH } else { 1 },
            cx,
            jump,
            end,
            each,
            forget
        );
        if moved == 0 {
            // The whole group goes on to the next instruction, where waiting members may
            // join it.
            pc += 1;
            if pc == waiting {
                waiting = END;
                for (k, &at) in pcs.iter().enumerate().take(n) {
                    if group & (1 << k) != 0 {
                        continue;
                    }
                    if at == pc {
                        group |= 1 << k;
                    } else {
                        waiting = waiting.min(at);
                    }
                }
            }
        } else if moved == group && !split && common < waiting {
            // The whole group jumped to one instruction before any waiting member's: it
            // goes on there together (what the general case below would find).
            pc = common;
        } else {
            // Members that did not jump go on to the next instruction; then the lowest
            // instruction any member is at runs next, for every member there.
            let mut rest = group & !moved;
            while rest != 0 {
                pcs[rest.trailing_zeros() as usize] = pc + 1;
                rest &= rest - 1;
            }
            let least = pcs[..n].iter().copied().min().unwrap_or(END);
            if least == END {
                // The last dispatch (the last members' `End`): its runs counted.
                #[cfg(feature = "profile")]
                if PROFILE && let Some((at, who, _)) = timed {
                    profile_dispatch(members, who, at, 0);
                }
                if LANES {
                    lanes.store(copies, members);
                }
                for ((cx, path), taken) in members.iter_mut().zip(paths).zip(takens) {
                    cx.path = if apart { path } else { shared };
                    cx.taken = if apart { taken } else { shared_taken };
                }
                return dispatches;
            }
            pc = least;
            group = 0;
            waiting = END;
            for (k, &at) in pcs.iter().enumerate().take(n) {
                if at == least {
                    group |= 1 << k;
                } else {
                    waiting = waiting.min(at);
                }
            }
        }
    }
}

/// Executes one instruction: `op` with its operands `o` (slot indices and jump targets, as
/// laid out in [`Op`]'s documentation) on the run's context, and returns the index of the
/// instruction to run next: `next` (the following one) unless the op jumps, [`END`] after
/// `End`.
///
/// Always inlined: in code generated ahead of time from a program (see [`crate::native`])
/// `op` and `o` are constants, so each call folds to that op's handler with its slot
/// indices as immediates.
///
/// # Safety
/// `op` and `o` must be an instruction of a program built by
/// [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) (with its operand window), and
/// `cx.slots` must cover that program's scalar slots (see the module docs).
#[inline(always)]
pub(crate) unsafe fn step(op: Op, o: &[u32], cx: &mut Ctx<'_>, next: usize) -> usize {
    macro_rules! jump {
        ($target:expr) => {
            return $target
        };
    }
    macro_rules! end {
        () => {
            return END
        };
    }
    let bases = Bases::of(cx.slots);
    let s = &mut *cx.slots;
    execute!(op, o, s, bases, 1, cx, jump, end, once, keep);
    next
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::one_bone;
    use crate::{FrameInput, Instance, ProgramBuilder};
    use std::sync::Arc;
    use strider_core::EmptyWorld;
    use strider_nodes::Value;

    /// A program whose path depends on the frame's dt `d`: an `if` (`y = 2d` when
    /// `d > 0.5`, else `y = d - 1`), a loop adding `d` to `acc` `trunc(d)` times, and two
    /// `End`s (`z = acc + y` when `d < 4`, else `z = 2 acc`). Returns the program and the
    /// slots of `y`, `acc` and `z`.
    fn branchy() -> (crate::Program, [usize; 3]) {
        let mut pb = ProgramBuilder::new("branchy");
        let c = |pb: &mut ProgramBuilder, v: f32| pb.constant(&Value::Float(v), "");
        let (half, one, two, four) = (
            c(&mut pb, 0.5),
            c(&mut pb, 1.0),
            c(&mut pb, 2.0),
            c(&mut pb, 4.0),
        );
        let zero_f = c(&mut pb, 0.0);
        let zero_i = pb.constant(&Value::Int(0), "");
        let [d, y, acc, z] = [(); 4].map(|()| pb.alloc(ValueType::Float));
        let [counter, count, index] = [(); 3].map(|()| pb.alloc(ValueType::Int));
        let [big, small] = [(); 2].map(|()| pb.alloc(ValueType::Bool));
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::DeltaTime, &[d]);
        pb.emit(Op::GreaterF, &[d, half, big]);
        let to_else = pb.emit(Op::JumpIfFalse, &[big, 0]);
        pb.emit(Op::MulF, &[d, two, y]);
        let to_join = pb.emit(Op::Jump, &[0]);
        let else_ = pb.emit(Op::SubF, &[d, one, y]);
        pb.patch(to_else, 1, else_);
        let join = pb.emit(Op::Copy(ValueType::Int), &[zero_i, counter]);
        pb.patch(to_join, 0, join);
        pb.emit(Op::Copy(ValueType::Float), &[zero_f, acc]);
        pb.emit(Op::ToInt, &[d, count]);
        let head = pb.emit(Op::ForNext, &[counter, count, index, 0]);
        pb.emit(Op::AddF, &[acc, d, acc]);
        pb.emit(Op::Jump, &[head]);
        let after = pb.emit(Op::LessF, &[d, four, small]);
        pb.patch(head, 3, after);
        let to_big = pb.emit(Op::JumpIfFalse, &[small, 0]);
        pb.emit(Op::AddF, &[acc, y, z]);
        pb.emit(Op::End, &[]);
        let big_end = pb.emit(Op::MulF, &[acc, two, z]);
        pb.patch(to_big, 1, big_end);
        pb.emit(Op::End, &[]);
        (pb.finish(), [y, acc, z].map(|s| s as usize))
    }

    #[test]
    fn a_batch_gives_every_member_its_own_path() {
        let (program, [y, acc, z]) = branchy();
        let program = Arc::new(program);
        let dts = [0.25, 0.75, 2.5, 4.0, 5.5, f32::NAN, 3.0];
        // (y, acc, z) by hand; NaN dt counts as 0.
        let expected = [
            (-0.75, 0.0, -0.75),
            (1.5, 0.0, 1.5),
            (5.0, 5.0, 10.0),
            (8.0, 16.0, 32.0),
            (11.0, 27.5, 55.0),
            (-1.0, 0.0, -1.0),
            (6.0, 9.0, 15.0),
        ];
        let mut crowd: Vec<Instance> = dts
            .iter()
            .map(|_| Instance::new(Arc::clone(&program), one_bone()).expect("instantiates"))
            .collect();
        let input = |k: usize| FrameInput {
            dt: dts[k],
            ..FrameInput::default()
        };
        // Twice: the second frame starts from the first one's state.
        for _ in 0..2 {
            Instance::run_forward_batch(&mut crowd, input, &EmptyWorld, false);
            for (k, instance) in crowd.iter().enumerate() {
                let f = &instance.slots().floats;
                assert_eq!(
                    (f[y], f[acc], f[z]),
                    expected[k],
                    "member {k}, dt {}",
                    dts[k]
                );
            }
        }
        // The same as each run alone for the same two frames, slot for slot (a loop that
        // runs no rounds leaves its index as it was, so each needs its own instance).
        for (k, instance) in crowd.iter().enumerate() {
            let mut alone = Instance::new(Arc::clone(&program), one_bone()).expect("instantiates");
            for _ in 0..2 {
                alone.run_forward(&input(k), &EmptyWorld, false);
            }
            assert!(alone.slots().bit_eq(instance.slots()), "member {k}");
        }
    }

    /// Reads of float arrays between writes of every kind: by the whole batch
    /// (`ArraySetAt`), by some members only (an `ArraySetAt` behind a branch, a `Select`
    /// into it, which leaves the members' lengths apart, an `ArrayAdd` behind a branch),
    /// by all through the handlers (an `ArrayAdd`, an `ArrayReset`, a `Copy` into it), with
    /// indices alike and apart, and a loop over one.
    /// Returns the program and the slots of the reads' results.
    fn array_reads() -> (crate::Program, [usize; 11]) {
        let mut pb = ProgramBuilder::new("array reads");
        let float = |pb: &mut ProgramBuilder, v: f32| pb.constant(&Value::Float(v), "");
        let int = |pb: &mut ProgramBuilder, v: i32| pb.constant(&Value::Int(v), "");
        let array = |pb: &mut ProgramBuilder, items: &[f32]| {
            let items = items.iter().map(|&x| Value::Float(x)).collect();
            pb.constant(&Value::Array(Elem::Float, items), "")
        };
        let (a, b, c) = (
            array(&mut pb, &[1.0, 2.0, 3.0]),
            array(&mut pb, &[7.0, 8.0]),
            array(&mut pb, &[5.0, 6.0, 7.0]),
        );
        let (half, ten) = (float(&mut pb, 0.5), float(&mut pb, 10.0));
        let [i0, i1, i2, i3, before] = [0, 1, 2, 3, -1].map(|v| int(&mut pb, v));
        let [d, sum, scaled] = [(); 3].map(|()| pb.alloc(ValueType::Float));
        let x = [(); 11].map(|()| pb.alloc(ValueType::Float));
        let [counter, index, count] = [(); 3].map(|()| pb.alloc(ValueType::Int));
        let (zero, element) = (float(&mut pb, 0.0), pb.alloc(ValueType::Float));
        let [big, small] = [(); 2].map(|()| pb.alloc(ValueType::Bool));
        let apart = pb.alloc(ValueType::Int);
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        let at = Op::ArrayAt(Elem::Float);
        pb.emit(Op::DeltaTime, &[d]);
        // Made at the first read, then written by the whole batch and read again.
        pb.emit(at, &[a, i1, x[0]]);
        pb.emit(Op::AddF, &[x[0], d, sum]);
        pb.emit(Op::ArraySetAt(Elem::Float), &[a, i1, sum]);
        // Read again and again (the batch runs on lanes with two instructions per slot).
        for _ in 0..32 {
            pb.emit(at, &[a, i1, x[1]]);
        }
        // Written by the members with a long time step only.
        pb.emit(Op::GreaterF, &[d, half, big]);
        let to_skip = pb.emit(Op::JumpIfFalse, &[big, 0]);
        pb.emit(Op::ArraySetAt(Elem::Float), &[a, i2, d]);
        let skip = pb.emit(at, &[a, i2, x[2]]);
        pb.patch(to_skip, 1, skip);
        // Grown by everyone, through the handlers, and read past the old end.
        pb.emit(Op::ArrayAdd(Elem::Float), &[a, d]);
        pb.emit(at, &[a, i3, x[3]]);
        // Indices apart: each member's own, some out of range.
        pb.emit(Op::MulF, &[d, ten, scaled]);
        pb.emit(Op::ToInt, &[scaled, apart]);
        pb.emit(at, &[a, apart, x[4]]);
        pb.emit(at, &[a, before, x[5]]);
        // Summed by a loop over it.
        pb.emit(Op::Copy(ValueType::Int), &[i0, counter]);
        pb.emit(Op::Copy(ValueType::Float), &[zero, x[10]]);
        let head = pb.emit(
            Op::ForEachNext(Elem::Float),
            &[a, counter, element, index, count, 0],
        );
        pb.emit(Op::AddF, &[x[10], element, x[10]]);
        pb.emit(Op::Jump, &[head]);
        let after = pb.here();
        pb.patch(head, 5, after);
        // Chosen by a select: b for the short steps, itself for the others (the lengths
        // part), then grown by the short steps only.
        pb.emit(Op::Not, &[big, small]);
        pb.emit(Op::Select(ValueType::Array(Elem::Float)), &[small, b, a, a]);
        pb.emit(at, &[a, i0, x[6]]);
        let to_join = pb.emit(Op::JumpIfFalse, &[small, 0]);
        pb.emit(Op::ArrayAdd(Elem::Float), &[a, d]);
        let join = pb.emit(at, &[a, i2, x[7]]);
        pb.patch(to_join, 1, join);
        // A third array read, then an emptied one copied into it.
        pb.emit(at, &[c, i0, x[8]]);
        pb.emit(Op::ArrayReset(Elem::Float), &[b]);
        pb.emit(Op::Copy(ValueType::Array(Elem::Float)), &[b, c]);
        pb.emit(at, &[c, i0, x[9]]);
        pb.emit(Op::End, &[]);
        (pb.finish(), x.map(|s| s as usize))
    }

    #[test]
    fn a_batch_reads_its_copies_of_arrays_as_each_member_reads_its_own() {
        let (program, x) = array_reads();
        assert!(lanes_pay_off(program.code.len(), &program.scalar_lens));
        let program = Arc::new(program);
        let dts = [0.25, 0.75, 0.125, 1.0, 0.5, 0.625, 0.375];
        let input = |k: usize| FrameInput {
            dt: dts[k],
            ..FrameInput::default()
        };
        let make = |n: usize| -> Vec<Instance> {
            (0..n)
                .map(|_| Instance::new(Arc::clone(&program), one_bone()).expect("instantiates"))
                .collect()
        };
        // A full batch and a short one.
        for n in [BATCH, dts.len()] {
            let input = |k: usize| input(k % dts.len());
            let (mut batched, mut alone) = (make(n), make(n));
            // Frame 1 by hand for dt 0.25 (member 0): 2 + 0.25 at index 1, then the
            // appended 0.25 at index 3 and index 2 (int(10 dt)) of [1, 2.25, 3, 0.25],
            // nothing at -1; b's 7 selected in, the short step's append to [7, 8, 0.25];
            // c's 5, then nothing in the emptied b copied into c; the loop's sum of
            // [1, 2.25, 3, 0.25].
            Instance::run_forward_batch(&mut batched, input, &EmptyWorld, false);
            let f = &batched[0].slots().floats;
            let got = x.map(|k| f[k]);
            let want = [2.0, 2.25, 3.0, 0.25, 3.0, 0.0, 7.0, 0.25, 5.0, 0.0, 6.5];
            assert_eq!(got, want, "n {n}");
            for (k, a) in alone.iter_mut().enumerate() {
                a.run_forward(&input(k), &EmptyWorld, false);
            }
            // Forty frames more: the arrays outgrow the copies' room.
            for _ in 0..40 {
                Instance::run_forward_batch(&mut batched, input, &EmptyWorld, false);
                for (k, a) in alone.iter_mut().enumerate() {
                    a.run_forward(&input(k), &EmptyWorld, false);
                }
                for (k, (b, a)) in batched.iter().zip(&alone).enumerate() {
                    assert!(a.slots().bit_eq(b.slots()), "n {n}, member {k}");
                }
            }
        }
    }

    /// `total += 2·dt` twelve times each frame through a temporary (`twice`), slots shared:
    /// `total` is read before it is written (kept from frame to frame), `dt` and `twice`
    /// live only within a run. Returns the program and `total`'s slot.
    fn accumulating() -> (crate::Program, usize) {
        let mut pb = ProgramBuilder::new("accumulating");
        let two = pb.constant(&Value::Float(2.0), "");
        let [d, twice, total] = [(); 3].map(|()| pb.alloc(ValueType::Float));
        pb.variable(crate::VariableInfo {
            name: "total".into(),
            ty: ValueType::Float,
            slot: total,
            default: Value::Float(0.0),
            tunable: None,
            location: String::new(),
        });
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::DeltaTime, &[d]);
        pb.emit(Op::MulF, &[d, two, twice]);
        for _ in 0..12 {
            pb.emit(Op::AddF, &[total, twice, total]);
        }
        pb.emit(Op::End, &[]);
        let program = pb.finish_sharing_slots();
        let total = program.variables()[0].slot as usize;
        (program, total)
    }

    #[test]
    fn a_batch_copies_back_what_outlives_the_run_and_with_debug_everything() {
        let (program, total) = accumulating();
        let float = 2;
        let (kept, written) = (program.kept_lens.0[float], program.written_lens.0[float]);
        assert!(total < kept, "the total is kept ({total} of {kept})");
        assert!(kept < written, "a temporary is shared ({kept}..{written})");
        assert!(lanes_pay_off(program.code.len(), &program.scalar_lens));
        let program = Arc::new(program);
        let dts = [0.25, 0.5, 1.0, 0.125];
        let input = |k: usize| FrameInput {
            dt: dts[k],
            ..FrameInput::default()
        };
        let make = || -> Vec<Instance> {
            dts.iter()
                .map(|_| Instance::new(Arc::clone(&program), one_bone()).expect("instantiates"))
                .collect()
        };
        let (mut batched, mut alone) = (make(), make());
        let initial = batched[0].slots().floats.clone();
        for frame in 1..=3 {
            Instance::run_forward_batch(&mut batched, input, &EmptyWorld, false);
            for (k, a) in alone.iter_mut().enumerate() {
                a.run_forward(&input(k), &EmptyWorld, false);
            }
            for (k, instance) in batched.iter().enumerate() {
                let f = &instance.slots().floats;
                // 24·dt per frame, exact in binary for these dts.
                assert_eq!(f[total], 24.0 * dts[k] * frame as f32, "member {k}");
                // The temporaries' slots are not copied back: as instantiated.
                assert_eq!(f[kept..written], initial[kept..written], "member {k}");
            }
        }
        // With debug every written slot comes back: the same as each run alone.
        Instance::run_forward_batch(&mut batched, input, &EmptyWorld, true);
        for (k, (b, a)) in batched.iter().zip(alone.iter_mut()).enumerate() {
            a.run_forward(&input(k), &EmptyWorld, true);
            assert!(a.slots().bit_eq(b.slots()), "member {k}");
        }
    }

    /// A world whose line trace runs a batch of a crowd of its own (as a host might, asking
    /// another rig something while it answers): the batch inside starts while the one
    /// outside holds this thread's lanes.
    struct NestedWorld {
        inner: std::sync::Mutex<Vec<Instance>>,
    }

    /// The dts of [`NestedWorld`]'s crowd.
    const INNER_DTS: [f32; 4] = [0.25, 2.5, 4.0, 5.5];

    impl strider_core::WorldQuery for NestedWorld {
        fn line_trace(&self, start: Vec3, end: Vec3) -> Option<strider_core::TraceHit> {
            let mut inner = self.inner.lock().expect("not poisoned");
            let input = |k: usize| FrameInput {
                dt: INNER_DTS[k],
                ..FrameInput::default()
            };
            Instance::run_forward_batch(&mut inner, input, &EmptyWorld, false);
            Some(strider_core::TraceHit {
                point: start.lerp(end, 0.5),
                normal: Vec3::Z,
                distance: start.distance(end) * 0.5,
            })
        }

        fn sphere_trace(&self, _: Vec3, _: Vec3, _: f32) -> Option<strider_core::TraceHit> {
            None
        }
    }

    #[test]
    fn a_batch_run_inside_another_on_one_thread_gets_lanes_of_its_own() {
        // Outside: each member traces from (0, 0, 10) down to (0, 0, −dt·10), scales the
        // hit distance by its dt and adds its dt 16 times (a program long enough for lanes).
        let mut pb = ProgramBuilder::new("tracer");
        let start = pb.constant(&Value::Vec3(Vec3::new(0.0, 0.0, 10.0)), "");
        let ten = pb.constant(&Value::Float(-10.0), "");
        let [d, depth, scaled] = [(); 3].map(|()| pb.alloc(ValueType::Float));
        let [end, point, normal] = [(); 3].map(|()| pb.alloc(ValueType::Vec3));
        let hit = pb.alloc(ValueType::Bool);
        let x = pb.alloc(ValueType::Float);
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::DeltaTime, &[d]);
        pb.emit(Op::MulF, &[d, ten, depth]);
        pb.emit(Op::MakeVector, &[x, x, depth, end]);
        pb.emit(Op::LineTrace, &[start, end, hit, point, normal, scaled]);
        pb.emit(Op::MulF, &[scaled, d, scaled]);
        for _ in 0..16 {
            pb.emit(Op::AddF, &[scaled, d, scaled]);
        }
        pb.emit(Op::End, &[]);
        let outer_program = Arc::new(pb.finish());
        let outer_dts = [1.0, 2.0, 0.5];
        let mut outer: Vec<Instance> = outer_dts
            .iter()
            .map(|_| Instance::new(Arc::clone(&outer_program), one_bone()).expect("instantiates"))
            .collect();

        // Inside: each member adds its dt to a sum 16 times a frame.
        let mut pb = ProgramBuilder::new("summing");
        let [d, sum] = [(); 2].map(|()| pb.alloc(ValueType::Float));
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::DeltaTime, &[d]);
        for _ in 0..16 {
            pb.emit(Op::AddF, &[sum, d, sum]);
        }
        pb.emit(Op::End, &[]);
        let inner_program = Arc::new(pb.finish());
        // Both run their batches on lanes, the inner one while the outer one holds them.
        for p in [&outer_program, &inner_program] {
            assert!(
                lanes_pay_off(p.code.len(), &p.scalar_lens),
                "{}",
                p.code.len()
            );
        }
        let crowd = |n: usize| -> Vec<Instance> {
            (0..n)
                .map(|_| {
                    Instance::new(Arc::clone(&inner_program), one_bone()).expect("instantiates")
                })
                .collect()
        };
        let world = NestedWorld {
            inner: std::sync::Mutex::new(crowd(INNER_DTS.len())),
        };
        let input = |k: usize| FrameInput {
            dt: outer_dts[k],
            ..FrameInput::default()
        };
        Instance::run_forward_batch(&mut outer, input, &world, false);

        // Outside: half the trace's length (10 + 10·dt), times dt.
        for (k, instance) in outer.iter().enumerate() {
            let dt = outer_dts[k];
            let f = &instance.slots().floats;
            let mut expected = (10.0 + 10.0 * dt) * 0.5 * dt;
            for _ in 0..16 {
                expected += dt;
            }
            assert_eq!(f[scaled as usize], expected, "member {k}");
        }
        // Inside: one frame per trace (three), the same as each instance run alone.
        let inner = world.inner.lock().expect("not poisoned");
        for (k, instance) in inner.iter().enumerate() {
            let mut alone = crowd(1).pop().expect("one");
            for _ in 0..outer_dts.len() {
                let input = FrameInput {
                    dt: INNER_DTS[k],
                    ..FrameInput::default()
                };
                alone.run_forward(&input, &EmptyWorld, false);
            }
            assert!(alone.slots().bit_eq(instance.slots()), "inner member {k}");
            // Three frames of 16 additions of its dt (exact in binary for these dts).
            assert_eq!(instance.slots().floats[sum as usize], 48.0 * INNER_DTS[k]);
        }
    }

    /// Dispatches of one batch run of `branchy` with these dts, the same on lanes and on the
    /// members' own slots (which also leave every member's slots the same).
    fn dispatches(dts: &[f32]) -> usize {
        let (on_lanes, lanes_slots) = dispatches_on::<true>(dts);
        let (own, own_slots) = dispatches_on::<false>(dts);
        assert_eq!(on_lanes, own, "dts {dts:?}");
        for (a, b) in lanes_slots.iter().zip(&own_slots) {
            assert!(a.bit_eq(b), "dts {dts:?}");
        }
        own
    }

    /// Dispatches of one batch run of `branchy` with these dts on lanes or not, and the
    /// members' slots after it.
    fn dispatches_on<const LANES: bool>(dts: &[f32]) -> (usize, Vec<Slots>) {
        let (program, _) = branchy();
        let skeleton = one_bone();
        let mut slots: Vec<Slots> = dts.iter().map(|_| program.initial.clone()).collect();
        let mut poses: Vec<Pose> = dts
            .iter()
            .map(|_| Pose::new(Arc::clone(&skeleton)))
            .collect();
        let mut draws: Vec<DebugDraw> = dts.iter().map(|_| DebugDraw::new(false)).collect();
        let mut members: Vec<Ctx<'_>> = slots
            .iter_mut()
            .zip(&mut poses)
            .zip(&mut draws)
            .zip(dts)
            .map(|(((slots, pose), debug), &dt)| {
                Ctx::for_test(slots, &program.texts, pose, debug, dt)
            })
            .collect();
        if dts.is_empty() {
            let n = run_batch(
                &program.code,
                &program.operands,
                program.forward,
                Copies::all(&program.scalar_lens),
                &mut members,
            );
            return (n, Vec::new());
        }
        let n = run_group::<LANES, false>(
            &program.code,
            &program.operands,
            program.forward,
            Copies::all(&program.scalar_lens),
            &mut members,
            &mut Lanes::default(),
        );
        drop(members);
        (n, slots)
    }

    #[test]
    fn only_programs_with_two_instructions_per_slot_run_on_lanes() {
        // pelvis_bob's 17 instructions over 20 slots, foot_ik's 104 over 57, locomotion's
        // 1 712 over 350.
        assert!(!lanes_pay_off(17, &ScalarLens([1, 1, 10, 5, 1, 2])));
        assert!(!lanes_pay_off(104, &ScalarLens([6, 2, 24, 17, 5, 3])));
        assert!(lanes_pay_off(1712, &ScalarLens([21, 13, 223, 61, 12, 20])));
        assert!(lanes_pay_off(4, &ScalarLens([1, 0, 1, 0, 0, 0])));
        assert!(!lanes_pay_off(3, &ScalarLens([1, 0, 1, 0, 0, 0])));
    }

    #[test]
    fn members_on_one_path_share_every_dispatch_and_split_paths_meet_again() {
        // Alone, dt 2.5 runs 19 instructions: 5 to the `if`'s join, 3 before the loop, 7
        // in it (two rounds of 3 and the exit), 4 after.
        assert_eq!(dispatches(&[2.5]), 19);
        assert_eq!(dispatches(&[2.5; 5]), 19, "one group throughout");
        // 0.75 takes the `then` side (13 alone), 0.25 the `else` side (12 alone): 3
        // together up to the branch, 2 for `then`, 1 for `else`, then 8 together again.
        assert_eq!(dispatches(&[0.75, 0.25]), 14);
        // 2.5 leaves the loop after two rounds, 4.0 after four: 8 together before the loop,
        // two rounds (6) and the third `ForNext` together, 4.0's two more rounds and exit
        // alone (6), the test after the loop together (2), then each member's own end (2
        // and 2).
        assert_eq!(dispatches(&[2.5, 4.0]), 27);
        assert_eq!(dispatches(&[]), 0);
    }
}
