//! The executor: a `match` loop over a program's instructions.
//!
//! Handlers trust the program: operand counts and slot types match each op's layout
//! ([`Op::operands`]). Scalar slots (bools, ints, floats, vectors, rotations, transforms)
//! are read and written without bounds checks, which is sound because:
//! - [`ProgramBuilder::finish`](crate::ProgramBuilder::finish) gives every scalar slot
//!   array of the program's initial memory a slot for every operand that the op's layout
//!   types as a slot of that type, so an instruction's slot operands are in bounds of the
//!   initial image;
//! - every run of an event first checks that the instance's arrays are still at least that
//!   long (growing them if not: `Instance::run_event`), and nothing shrinks them during a
//!   run;
//! - each handler reads operand `k` only through the accessor of the type the op's layout
//!   gives position `k` (every access asserts its bound in debug builds, where the test
//!   suite runs every op).
//!
//! Instructions and their operand windows are fetched without bounds checks too:
//! `ProgramBuilder::finish` makes sure every jump target and event entry is an
//! instruction, that the last instruction cannot fall through past the end, and pads the
//! operand list by `MAX_OPERANDS` past every instruction's first operand.
//!
//! Array slots, bones, names and the elements of arrays keep their bounds checks.

// Unchecked slot access and instruction fetch (see above) are this module's only unsafe
// code.
#![allow(unsafe_code)]

use crate::program::{Instr, Program};
use crate::slots::Slots;
use glam::{Quat, Vec3};
use strider_core::{BoneIndex, DebugColor, DebugDraw, DebugPrimitive, Pose, Transform, WorldQuery};
use strider_nodes::kernels as k;
use strider_nodes::kernels::locomotion as loco;
use strider_nodes::kernels::spline::{self, SplineMode};
use strider_nodes::kernels::two_bone_ik::{Pole, TwoBoneIk};
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
    /// `to_world.inverse()`, computed once per run (traces bring hits back to rig space).
    pub from_world: Transform,
    /// Number of this run (construction or frame), never 0: stateful nodes advance once per
    /// run and remember the run they last advanced in.
    pub run: i32,
    /// Where to accumulate per-instruction time and counts (indexed by instruction), when
    /// profiling is on.
    #[cfg(feature = "profile")]
    pub profile: Option<&'a mut [crate::profile::InstrProfile]>,
}

/// A bone slot's value as an index into the pose, if it names a bone.
#[inline]
fn bone(pose: &Pose, value: i32) -> Option<BoneIndex> {
    (value >= 0 && (value as usize) < pose.len()).then_some(BoneIndex(value as u32))
}

fn color(v: Vec3) -> DebugColor {
    DebugColor([v.x, v.y, v.z, 1.0])
}

/// Dispatches a per-element-type handler: `$m!(scalars, arrays, zero)`.
macro_rules! by_elem {
    ($e:expr, $s:expr, $m:ident) => {
        match $e {
            Elem::Bool => $m!($s.bools, $s.bool_arrays, false),
            Elem::Int => $m!($s.ints, $s.int_arrays, 0),
            Elem::Float => $m!($s.floats, $s.float_arrays, 0.0),
            Elem::Vec3 => $m!($s.vec3s, $s.vec3_arrays, Vec3::ZERO),
            Elem::Quat => $m!($s.quats, $s.quat_arrays, Quat::IDENTITY),
            Elem::Transform => $m!($s.transforms, $s.transform_arrays, Transform::IDENTITY),
            Elem::Bone => $m!($s.bones, $s.bone_arrays, -1),
        }
    };
}

/// Copies within one slot array; arrays reuse the destination's memory.
fn copy_vec<T: Clone>(v: &mut [Vec<T>], from: usize, to: usize) {
    if from != to {
        let src = std::mem::take(&mut v[from]);
        v[to].clone_from(&src);
        v[from] = src;
    }
}

/// The "next instruction" of an `End`: the event is over.
pub(crate) const END: usize = usize::MAX;

/// The base pointers of an instance's scalar slot arrays. Valid for a whole run of an event:
/// nothing resizes the scalar arrays during a run (arrays of arrays may grow; they are
/// separate allocations).
#[derive(Clone, Copy)]
struct Bases {
    bools: *mut bool,
    ints: *mut i32,
    floats: *mut f32,
    vec3s: *mut Vec3,
    quats: *mut Quat,
    transforms: *mut Transform,
}

impl Bases {
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
/// borrowed apart so the interpreter can hold it across instructions), whose scalar arrays
/// start at `$bases` ([`Bases`]), and context `$cx`.
///
/// Expanded twice: in the interpreter loop ([`run_loop`]) and in [`step`], the entry point
/// of code generated ahead of time. After a control op the expansion site decides what
/// happens: `$jump!(target)` continues at instruction `target`, `$end!()` ends the event.
macro_rules! execute {
    ($op:expr, $o:expr, $s:expr, $bases:expr, $cx:ident, $jump:ident, $end:ident) => {{
        let (op, o): (Op, &[u32]) = ($op, $o);
        let s: &mut Slots = $s;
        let bases: Bases = $bases;
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
                debug_assert!(index < s.$a.len(), "{op:?} operand {} out of bounds", $k);
                // SAFETY: in bounds by the module's invariant (the program's layout check
                // and the per-run length check), and the base pointer is current (see
                // `Bases`); the reference lives for one read or write.
                unsafe { &mut *bases.$a.add(index) }
            }};
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
                let result = match bone($cx.pose, s.bones[at!($b)]) {
                    None => Transform::IDENTITY,
                    Some(bi) => {
                        let global = i!($b + 1) == 0;
                        match (b!($b + 2), global) {
                            (true, true) => $cx.pose.skeleton().rest_global(bi),
                            (true, false) => $cx.pose.skeleton().rest_local(bi),
                            (false, true) => $cx.pose.global(bi),
                            (false, false) => $cx.pose.local(bi),
                        }
                    }
                };
                t!($b + 3) = result;
            }};
        }
        macro_rules! array_at {
            ($e:expr, $b:expr) => {{
                let index = i!($b + 1);
                macro_rules! get {
                    ($sc:expr, $ar:expr, $zero:expr) => {{
                        let a = &$ar[at!($b)];
                        $sc[at!($b + 2)] = if index >= 0 {
                            a.get(index as usize).copied().unwrap_or($zero)
                        } else {
                            $zero
                        };
                    }};
                }
                by_elem!($e, s, get);
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
                    ValueType::Bone => s.bones[at!(to_k)] = s.bones[at!(from_k)],
                    ValueType::Name => s.names[at!(to_k)] = s.names[at!(from_k)],
                    ValueType::Array(e) => {
                        let (from, to) = (at!(from_k), at!(to_k));
                        macro_rules! copy {
                            ($sc:expr, $ar:expr, $zero:expr) => {
                                copy_vec(&mut $ar, from, to)
                            };
                        }
                        by_elem!(e, s, copy);
                    }
                }
            }};
        }
        match op {
            Op::End => $end!(),
            Op::Jump => $jump!(o[0] as usize),
            Op::JumpIfFalse => {
                if !b!(0) {
                    $jump!(o[1] as usize);
                }
            }
            Op::ForEachNext(e) => {
                let counter = i!(1);
                macro_rules! next {
                    ($sc:expr, $ar:expr, $zero:expr) => {{
                        let len = $ar[at!(0)].len();
                        if counter < 0 || counter as usize >= len {
                            $jump!(o[5] as usize);
                        } else {
                            $sc[at!(2)] = $ar[at!(0)][counter as usize];
                            i!(3) = counter;
                            i!(4) = len as i32;
                            i!(1) = counter + 1;
                        }
                    }};
                }
                by_elem!(e, s, next);
            }
            Op::ForNext => {
                let counter = i!(0);
                if counter >= i!(1) {
                    $jump!(o[3] as usize);
                } else {
                    i!(2) = counter;
                    i!(0) = counter + 1;
                }
            }
            Op::Copy(ty) => copy_slot!(ty, 0, 1),
            Op::IntToFloat | Op::ToFloat => f!(1) = i!(0) as f32,

            Op::AddF => arith!(AddF, 0),
            Op::SubF => arith!(SubF, 0),
            Op::MulF => arith!(MulF, 0),
            Op::DivF => arith!(DivF, 0),
            Op::MinF => f!(2) = f!(0).min(f!(1)),
            Op::MaxF => f!(2) = f!(0).max(f!(1)),
            Op::AbsF => f!(1) = f!(0).abs(),
            Op::NegF => f!(1) = -f!(0),
            Op::ClampF => f!(3) = k::clamp_f(f!(0), f!(1), f!(2)),
            Op::SinF => f!(1) = k::sin_deg(f!(0)),
            Op::CosF => f!(1) = k::cos_deg(f!(0)),
            Op::TanF => f!(1) = k::tan_deg(f!(0)),
            Op::Atan2F => f!(2) = k::atan2_deg(f!(0), f!(1)),
            Op::SqrtF => f!(1) = k::sqrt(f!(0)),
            Op::PowF => f!(2) = f!(0).powf(f!(1)),
            Op::FmodF => f!(2) = k::mod_f(f!(0), f!(1)),
            Op::FractF => f!(1) = k::fract(f!(0)),
            Op::FloorF => f!(1) = f!(0).floor(),
            Op::CeilF => f!(1) = f!(0).ceil(),
            Op::RoundF => f!(1) = f!(0).round(),
            Op::LerpF => f!(3) = f!(0) + (f!(1) - f!(0)) * f!(2),
            Op::RemapF => f!(6) = k::remap(f!(0), f!(1), f!(2), f!(3), f!(4), b!(5)),
            Op::SmoothStepF => f!(3) = k::smooth_step(f!(0), f!(1), f!(2)),
            Op::ToInt => i!(1) = k::to_int(f!(0)),

            Op::AddI => i!(2) = i!(0).wrapping_add(i!(1)),
            Op::SubI => i!(2) = i!(0).wrapping_sub(i!(1)),
            Op::MulI => i!(2) = i!(0).wrapping_mul(i!(1)),
            Op::DivI => i!(2) = k::div_i(i!(0), i!(1)),
            Op::ModI => i!(2) = k::mod_i(i!(0), i!(1)),
            Op::MinI => i!(2) = i!(0).min(i!(1)),
            Op::MaxI => i!(2) = i!(0).max(i!(1)),
            Op::AbsI => i!(1) = i!(0).wrapping_abs(),
            Op::NegI => i!(1) = i!(0).wrapping_neg(),
            Op::ClampI => i!(3) = i!(0).max(i!(1)).min(i!(2)),

            Op::And => b!(2) = b!(0) && b!(1),
            Op::Or => b!(2) = b!(0) || b!(1),
            Op::Xor => b!(2) = b!(0) != b!(1),
            Op::Not => b!(1) = !b!(0),
            Op::Equals(e) | Op::NotEquals(e) => {
                let eq = match e {
                    Elem::Float => f!(0) == f!(1),
                    Elem::Int => i!(0) == i!(1),
                    Elem::Bool => b!(0) == b!(1),
                    Elem::Bone => s.bones[at!(0)] == s.bones[at!(1)],
                    Elem::Vec3 => v!(0) == v!(1),
                    Elem::Quat => q!(0) == q!(1),
                    Elem::Transform => t!(0) == t!(1),
                };
                b!(2) = eq == matches!(op, Op::Equals(_));
            }
            Op::LessF => b!(2) = f!(0) < f!(1),
            Op::LessEqualF => b!(2) = f!(0) <= f!(1),
            Op::GreaterF => b!(2) = f!(0) > f!(1),
            Op::GreaterEqualF => b!(2) = f!(0) >= f!(1),
            Op::LessI => b!(2) = i!(0) < i!(1),
            Op::LessEqualI => b!(2) = i!(0) <= i!(1),
            Op::GreaterI => b!(2) = i!(0) > i!(1),
            Op::GreaterEqualI => b!(2) = i!(0) >= i!(1),
            Op::Select(ty) => copy_slot!(ty, if b!(0) { 1 } else { 2 }, 3),

            Op::AddV => arith!(AddV, 0),
            Op::SubV => arith!(SubV, 0),
            Op::MulV => v!(2) = v!(0) * v!(1),
            Op::DivV => v!(2) = k::div_v(v!(0), v!(1)),
            Op::ScaleV => arith!(ScaleV, 0),
            Op::NegV => v!(1) = -v!(0),
            Op::MinV => v!(2) = v!(0).min(v!(1)),
            Op::MaxV => v!(2) = v!(0).max(v!(1)),
            Op::AbsV => v!(1) = v!(0).abs(),
            Op::ClampV => v!(3) = v!(0).max(v!(1)).min(v!(2)),
            Op::LerpV => v!(3) = v!(0).lerp(v!(1), f!(2)),
            Op::LengthV => f!(1) = v!(0).length(),
            Op::DistanceV => f!(2) = v!(0).distance(v!(1)),
            Op::UnitV => v!(1) = k::unit_v(v!(0)),
            Op::DotV => f!(2) = v!(0).dot(v!(1)),
            Op::CrossV => v!(2) = v!(0).cross(v!(1)),
            Op::MakeVector => v!(3) = Vec3::new(f!(0), f!(1), f!(2)),
            Op::BreakVector => {
                let x = v!(0);
                f!(1) = x.x;
                f!(2) = x.y;
                f!(3) = x.z;
            }

            Op::QuatFromAxisAngle => q!(2) = k::quat_from_axis_angle(v!(0), f!(1)),
            Op::QuatFromEuler => {
                q!(2) = strider_core::euler::quat_from_euler(v!(0), k::euler_order(i!(1)));
            }
            Op::EulerFromQuat => {
                v!(2) = strider_core::euler::euler_from_quat(q!(0), k::euler_order(i!(1)));
            }
            Op::MulQ => q!(2) = k::unit_q(q!(0) * q!(1)),
            Op::InverseQ => q!(1) = k::unit_q(q!(0)).inverse(),
            Op::UnitQ => q!(1) = k::unit_q(q!(0)),
            Op::SlerpQ => q!(3) = k::slerp(q!(0), q!(1), f!(2)),
            Op::RotateVector => v!(2) = q!(0) * v!(1),
            Op::QuatScale => q!(2) = k::quat_scale(q!(0), f!(1)),
            Op::FindQuatBetween => q!(2) = k::find_quat_between(v!(0), v!(1)),

            Op::MakeTransform => t!(3) = Transform::new(v!(0), k::unit_q(q!(1)), v!(2)),
            Op::BreakTransform => break_transform!(0),
            Op::MulT => t!(2) = t!(0) * t!(1),
            Op::InverseT => t!(1) = t!(0).inverse(),
            Op::MakeRelative => t!(2) = t!(0).relative_to(&t!(1)),
            Op::MakeAbsolute => t!(2) = t!(1) * t!(0),
            Op::TransformPoint => v!(2) = t!(0).transform_point(v!(1)),
            Op::TransformVector => v!(2) = t!(0).transform_vector(v!(1)),
            Op::RotateAroundPoint => t!(3) = k::rotate_around_point(t!(0), v!(1), q!(2)),
            Op::InterpolateTransform => {
                let w = f!(2);
                t!(3) = if w.is_nan() {
                    t!(0)
                } else {
                    t!(0).interpolate(&t!(1), w)
                };
            }
            Op::AimMath => {
                let tr = t!(0);
                let target = v!(2);
                let direction = if i!(3) == 0 {
                    target
                } else {
                    target - tr.translation
                };
                t!(5) = k::aim(tr, v!(1), direction, f!(4));
            }
            Op::AlignToNormal => t!(4) = k::aim(t!(0), v!(1), v!(2), f!(3)),
            Op::Spline => {
                let mode = if i!(2) == 1 {
                    SplineMode::CatmullRom
                } else {
                    SplineMode::BSpline
                };
                let (p, t) = spline::evaluate(&s.vec3_arrays[at!(0)], f!(1), mode);
                v!(3) = p;
                v!(4) = t;
            }
            Op::ClampLength => v!(3) = k::clamp_length(v!(0), f!(1), f!(2)),
            Op::ClampSpatially => v!(4) = k::clamp_spatially(v!(0), v!(1), f!(2), f!(3)),

            Op::GetTransform => get_transform!(0),
            Op::SetTransform => {
                if let Some(bi) = bone($cx.pose, s.bones[at!(0)]) {
                    let weight = f!(4);
                    if i!(2) == 0 {
                        let value = k::blend_transform($cx.pose.global(bi), t!(1), weight);
                        $cx.pose.set_global(bi, value, b!(3));
                    } else {
                        let value = k::blend_transform($cx.pose.local(bi), t!(1), weight);
                        $cx.pose.set_local(bi, value);
                    }
                }
            }
            Op::GetParent => {
                s.bones[at!(1)] = match bone($cx.pose, s.bones[at!(0)]) {
                    Some(bi) => $cx.pose.skeleton().parent(bi).map_or(-1, |p| p.0 as i32),
                    None => -1,
                };
            }
            Op::FindBones => {
                let out = &mut s.bone_arrays[at!(3)];
                match bone($cx.pose, s.bones[at!(0)]) {
                    Some(root) => {
                        let contains = &$cx.texts[s.names[at!(1)] as usize];
                        let excludes = &$cx.texts[s.names[at!(2)] as usize];
                        k::find_bones($cx.pose.skeleton(), root, contains, excludes, out);
                    }
                    None => out.clear(),
                }
            }
            Op::TwoBoneIK => {
                let chain = (
                    bone($cx.pose, s.bones[at!(0)]),
                    bone($cx.pose, s.bones[at!(1)]),
                    bone($cx.pose, s.bones[at!(2)]),
                );
                let (reached, distance) = match chain {
                    (Some(a), Some(b), Some(c)) => {
                        let pole = if i!(7) == 1 {
                            Pole::Location(v!(6))
                        } else {
                            Pole::Direction(v!(6))
                        };
                        let ik = TwoBoneIk {
                            primary_axis: v!(4),
                            secondary_axis: v!(5),
                            pole,
                            weight: f!(8),
                            stretch: b!(9).then_some((f!(10), f!(11))),
                            set_effector_rotation: b!(12),
                        };
                        let report = ik.solve($cx.pose, a, b, c, t!(3));
                        (report.reached, report.distance_to_target)
                    }
                    _ => (false, f32::INFINITY),
                };
                b!(13) = reached;
                f!(14) = distance;
            }
            Op::DeltaTime => f!(0) = $cx.dt,
            Op::WorldTransform => t!(0) = $cx.to_world,
            Op::LineTrace | Op::SphereTrace => {
                let (start, end) = (v!(0), v!(1));
                let (ws, we) = (
                    $cx.to_world.transform_point(start),
                    $cx.to_world.transform_point(end),
                );
                let (hit, outs) = if op == Op::LineTrace {
                    ($cx.world.line_trace(ws, we), 2)
                } else {
                    ($cx.world.sphere_trace(ws, we, f!(2).max(0.0)), 3)
                };
                let hit = hit.filter(|h| {
                    h.point.is_finite() && h.normal.is_finite() && h.distance.is_finite()
                });
                match hit {
                    Some(h) => {
                        let from_world = $cx.from_world;
                        b!(outs) = true;
                        v!(outs + 1) = from_world.transform_point(h.point);
                        v!(outs + 2) = k::unit_v(from_world.transform_vector(h.normal));
                        f!(outs + 3) = h.distance;
                    }
                    None => {
                        b!(outs) = false;
                        v!(outs + 1) = end;
                        v!(outs + 2) = Vec3::Z;
                        f!(outs + 3) = start.distance(end);
                    }
                }
            }

            Op::FloatLerp => f!(3) = loco::lerp_exponential(f!(0), f!(1), $cx.dt, f!(2)),
            Op::VectorLerp => {
                let max = f!(3);
                v!(4) = if max > 0.0 {
                    loco::lerp_max_step(v!(0), v!(1), $cx.dt, f!(2), max)
                } else {
                    loco::lerp_exponential_v(v!(0), v!(1), $cx.dt, f!(2))
                };
            }
            Op::QuatLerp => q!(3) = loco::lerp_exponential_q(q!(0), q!(1), $cx.dt, f!(2)),
            Op::FInterpToF => f!(3) = loco::finterp_to(f!(0), f!(1), $cx.dt, f!(2)),
            Op::FInterpToV => v!(3) = loco::vinterp_to(v!(0), v!(1), $cx.dt, f!(2)),
            Op::FInterpToQ => q!(3) = loco::qinterp_to(q!(0), q!(1), $cx.dt, f!(2)),
            Op::SpringF => {
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
            }
            Op::SpringV => {
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
            }
            Op::MovementAngleOffset => {
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
            }
            Op::PerFootRotationFactor => {
                f!(3) = loco::per_foot_rotation_factor(f!(0), f!(1), f!(2))
            }
            Op::LimitRotationAroundZ => q!(3) = loco::limit_rotation_around_z(q!(0), f!(1), f!(2)),
            Op::FootAvoidance => v!(5) = loco::foot_avoidance(v!(0), v!(1), f!(2), b!(3), f!(4)),
            Op::KneeVector => v!(5) = loco::knee_vector(q!(0), q!(1), v!(2), f!(3), f!(4)),
            Op::ArmSwingRotation => {
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
            }
            Op::ClavicleOffset => f!(4) = loco::clavicle_offset(f!(0), f!(1), f!(2), f!(3)),
            Op::PelvisLean => {
                let (pitch, shift) = loco::pelvis_lean(v!(0), f!(1), f!(2), f!(3));
                f!(4) = pitch;
                f!(5) = shift;
            }
            Op::PelvisSideLean => f!(3) = loco::pelvis_side_lean(f!(0), f!(1), f!(2)),
            Op::FootPivots => {
                let (ball, tip, heel) = loco::foot_pivots(v!(0), v!(1), f!(2), f!(3), f!(4), f!(5));
                v!(6) = ball;
                v!(7) = tip;
                v!(8) = heel;
            }
            Op::CycleStep => {
                let (master, per_foot) = loco::cycle_step(f!(0), $cx.dt, f!(1), f!(2), b!(3));
                f!(4) = master;
                f!(5) = per_foot;
            }
            Op::FootOffsetFromTrace => f!(3) = loco::foot_offset_from_trace(b!(0), f!(1), f!(2)),
            Op::RotationFromNormal => {
                let n = v!(0);
                let (pitch, roll) = loco::rotation_from_normal(n);
                f!(1) = pitch;
                f!(2) = roll;
                q!(3) = loco::rotation_from_normal_quat(n);
            }

            Op::ArrayAt(e) => array_at!(e, 0),
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
            Op::GetTransformBreakTransform => {
                get_transform!(0);
                break_transform!(4);
            }
            Op::ArrayAtBreakTransform => {
                array_at!(Elem::Transform, 0);
                break_transform!(3);
            }
            Op::ArrayCount(e) => {
                macro_rules! count {
                    ($sc:expr, $ar:expr, $zero:expr) => {
                        s.ints[at!(1)] = $ar[at!(0)].len() as i32
                    };
                }
                by_elem!(e, s, count);
            }
            Op::ArraySetAt(e) => {
                let index = i!(1);
                macro_rules! set {
                    ($sc:expr, $ar:expr, $zero:expr) => {{
                        let value = $sc[at!(2)];
                        if index >= 0 {
                            if let Some(x) = $ar[at!(0)].get_mut(index as usize) {
                                *x = value;
                            }
                        }
                    }};
                }
                by_elem!(e, s, set);
            }
            Op::ArrayAdd(e) => {
                macro_rules! add {
                    ($sc:expr, $ar:expr, $zero:expr) => {{
                        let value = $sc[at!(1)];
                        $ar[at!(0)].push(value);
                    }};
                }
                by_elem!(e, s, add);
            }
            Op::ArrayReset(e) => {
                macro_rules! reset {
                    ($sc:expr, $ar:expr, $zero:expr) => {
                        $ar[at!(0)].clear()
                    };
                }
                by_elem!(e, s, reset);
            }

            // Draw ops: DebugDraw::push records nothing when drawing is off.
            Op::DrawPoint => {
                $cx.debug.push(DebugPrimitive::Point {
                    position: v!(0),
                    size: f!(1),
                    color: color(v!(2)),
                });
            }
            Op::DrawLine => {
                $cx.debug.push(DebugPrimitive::Line {
                    start: v!(0),
                    end: v!(1),
                    thickness: f!(2),
                    color: color(v!(3)),
                });
            }
            Op::DrawArrow => {
                $cx.debug.push(DebugPrimitive::Arrow {
                    start: v!(0),
                    end: v!(1),
                    thickness: f!(2),
                    color: color(v!(3)),
                });
            }
            Op::DrawSphere => {
                $cx.debug.push(DebugPrimitive::Sphere {
                    center: v!(0),
                    radius: f!(1),
                    color: color(v!(2)),
                });
            }
            Op::DrawBox => {
                $cx.debug.push(DebugPrimitive::Box {
                    transform: t!(0),
                    half_extents: v!(1),
                    color: color(v!(2)),
                });
            }
            Op::DrawSpline => {
                if $cx.debug.is_enabled() {
                    let mode = if i!(1) == 1 {
                        SplineMode::CatmullRom
                    } else {
                        SplineMode::BSpline
                    };
                    let pieces = i!(2).clamp(1, 256);
                    let points = &s.vec3_arrays[at!(0)];
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
            }
            Op::DrawTransform => {
                $cx.debug.push(DebugPrimitive::Axes {
                    transform: t!(0),
                    size: f!(1),
                    thickness: f!(2),
                });
            }
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
    loop {
        #[cfg(feature = "profile")]
        let here = pc;
        // SAFETY: `pc` is an instruction: the entry and every jump target are (checked by
        // `ProgramBuilder::finish`), and the last instruction cannot fall through.
        let Instr { op, args } = unsafe { *code.get_unchecked(pc) };
        pc += 1;
        macro_rules! jump {
            ($target:expr) => {
                pc = $target
            };
        }
        macro_rules! end {
            () => {{
                #[cfg(feature = "profile")]
                if PROFILE {
                    // `End` counts as run but takes no time of its own.
                    profile[here].count += 1;
                }
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
            &mut *s,
            bases,
            cx,
            jump,
            end
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
    execute!(op, o, &mut *cx.slots, bases, cx, jump, end);
    next
}
