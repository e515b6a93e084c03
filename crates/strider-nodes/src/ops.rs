//! The instruction set: what a compiled node or control-flow step does.
//!
//! Each [`Op`] reads and writes typed slots whose indices follow in the program's operand
//! list, in a fixed layout: for node ops, the overload's inputs in table order, then its
//! outputs (see [`crate::table::Overload`]); for the control ops, the layout documented on
//! the variant. The executor is a `match` over this enum.

use crate::types::{Elem, ValueType};
use std::borrow::Cow;

/// The most operands any instruction has: the executor reads each instruction's operands
/// as a window of this many (the program's operand list is padded at its end), so the
/// handlers' operand reads need no bounds checks of their own.
pub const MAX_OPERANDS: usize = 16;

/// What one operand of an instruction is (see [`Op::operands`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operand {
    /// The index of a slot of this type, and what the instruction does with it.
    Slot(ValueType, Access),
    /// An instruction index to continue at.
    Target,
}

/// What an instruction does with one of its slot operands.
///
/// An instruction with a jump target writes its [`Access::Write`] and
/// [`Access::ReadWrite`] operands only when it does not jump (a loop step that leaves the
/// loop sets nothing); every other instruction writes each of them every time it runs,
/// whatever its inputs. Slot sharing (`strider_vm`) relies on both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Only read.
    Read,
    /// Only written, with a value that does not depend on what the slot held.
    Write,
    /// Read, then written (a node's state, a loop counter, an array edited in place).
    ReadWrite,
}

impl Op {
    /// This op's operands, in order: for node ops the overload's inputs, outputs and state
    /// (from the node table), for fused ops their two parts' laid end to end (also from the
    /// node table), for control ops the layout documented on the variant. `None` for an op
    /// that no node compiles to and the compiler never emits.
    ///
    /// The executor reads slot operands without bounds checks: a program is only built once
    /// every slot operand, read by this layout, names an existing slot of its type.
    #[must_use]
    pub fn operands(self) -> Option<Cow<'static, [Operand]>> {
        use Access::{Read, ReadWrite, Write};
        use Operand::{Slot, Target};
        use ValueType as T;
        Some(match self {
            Op::End => Cow::Borrowed(&[]),
            Op::Jump => Cow::Borrowed(&[Target]),
            Op::JumpIfFalse => Cow::Borrowed(&[Slot(T::Bool, Read), Target]),
            Op::ForEachNext(e) => Cow::Owned(vec![
                Slot(T::Array(e), Read),
                Slot(T::Int, ReadWrite),
                Slot(e.scalar(), Write),
                Slot(T::Int, Write),
                Slot(T::Int, Write),
                Target,
            ]),
            Op::ForNext => Cow::Borrowed(&[
                Slot(T::Int, ReadWrite),
                Slot(T::Int, Read),
                Slot(T::Int, Write),
                Target,
            ]),
            Op::Copy(ty) => Cow::Owned(vec![Slot(ty, Read), Slot(ty, Write)]),
            Op::IntToFloat => Cow::Borrowed(&[Slot(T::Int, Read), Slot(T::Float, Write)]),
            // Node ops and fused ops: laid out once, when the registry is built.
            op => Cow::Borrowed(crate::registry().layout(op)?),
        })
    }

    /// The fused ops (superinstructions), each with the two ops it runs, one after the
    /// other, on their operand lists laid end to end.
    pub const FUSED: [(Op, (Op, Op)); 14] = [
        (Op::MulFMulF, (Op::MulF, Op::MulF)),
        (Op::SubFMulF, (Op::SubF, Op::MulF)),
        (Op::MulFAddF, (Op::MulF, Op::AddF)),
        (Op::SubFAddF, (Op::SubF, Op::AddF)),
        (Op::AddFMulF, (Op::AddF, Op::MulF)),
        (Op::MulFSubF, (Op::MulF, Op::SubF)),
        (Op::AddFAddF, (Op::AddF, Op::AddF)),
        (Op::DivFSubF, (Op::DivF, Op::SubF)),
        (Op::AddVAddV, (Op::AddV, Op::AddV)),
        (Op::AddVSubV, (Op::AddV, Op::SubV)),
        (Op::MulFScaleV, (Op::MulF, Op::ScaleV)),
        (Op::DivFScaleV, (Op::DivF, Op::ScaleV)),
        (
            Op::GetTransformBreakTransform,
            (Op::GetTransform, Op::BreakTransform),
        ),
        (
            Op::ArrayAtBreakTransform,
            (Op::ArrayAt(Elem::Transform), Op::BreakTransform),
        ),
    ];

    /// The two ops a fused op runs, in order ([`Op::FUSED`]); `None` for any other op.
    #[must_use]
    pub fn fused_parts(self) -> Option<(Op, Op)> {
        Op::FUSED
            .iter()
            .find(|(fused, _)| *fused == self)
            .map(|&(_, parts)| parts)
    }

    /// Whether this is a debug-drawing op: one that only records a primitive in the run's
    /// debug output, when that output is enabled, and touches nothing else.
    #[must_use]
    pub fn is_draw(self) -> bool {
        matches!(self, crate::draw_ops!())
    }
}

/// A pattern matching every debug-drawing op ([`Op::is_draw`]), for a `match` arm of its
/// own: `strider_nodes::draw_ops!() => ...`.
#[macro_export]
macro_rules! draw_ops {
    () => {
        $crate::Op::DrawPoint
            | $crate::Op::DrawLine
            | $crate::Op::DrawArrow
            | $crate::Op::DrawSphere
            | $crate::Op::DrawBox
            | $crate::Op::DrawSpline
            | $crate::Op::DrawTransform
    };
}

/// One instruction kind. Variants that carry a type are a family of ops whose handler is
/// the same but for the slot array it touches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    // ---- control (emitted by the compiler, not nodes) ----
    /// Stop the event. No operands.
    End,
    /// `[target]`: continue at instruction `target`.
    Jump,
    /// `[cond: Bool, target]`: continue at `target` when `cond` is false.
    JumpIfFalse,
    /// `[array, counter: Int, element, index: Int, count: Int, exit]`: when
    /// `counter >= len(array)` jump to `exit`; else load the element, set index and count,
    /// and advance the counter.
    ForEachNext(Elem),
    /// `[counter: Int, count: Int, index: Int, exit]`: a counted loop step.
    ForNext,
    /// `[from, to]`: copy a slot of the given type (arrays keep their capacity).
    Copy(ValueType),
    /// `[from: Int, to: Float]`: the implicit lossless conversion.
    IntToFloat,

    // ---- fused: two adjacent instructions joined into one (the VM's superinstructions) ----
    // Each runs its two ops one after the other on their operand lists laid end to end:
    // `[a, b, x, c, d, y]` for two arithmetic ops, `x` the first's result and `y` the
    // second's (which usually reads `x`). See `Op::FUSED`.
    /// `MulF` then `MulF`.
    MulFMulF,
    /// `SubF` then `MulF`.
    SubFMulF,
    /// `MulF` then `AddF`.
    MulFAddF,
    /// `SubF` then `AddF`.
    SubFAddF,
    /// `AddF` then `MulF`.
    AddFMulF,
    /// `MulF` then `SubF`.
    MulFSubF,
    /// `AddF` then `AddF`.
    AddFAddF,
    /// `DivF` then `SubF`.
    DivFSubF,
    /// `AddV` then `AddV`.
    AddVAddV,
    /// `AddV` then `SubV`.
    AddVSubV,
    /// `MulF` then `ScaleV`.
    MulFScaleV,
    /// `DivF` then `ScaleV`.
    DivFScaleV,
    /// `GetTransform` then `BreakTransform`.
    GetTransformBreakTransform,
    /// `ArrayAt(Transform)` then `BreakTransform`.
    ArrayAtBreakTransform,

    // ---- float ----
    /// Float sum.
    AddF,
    /// Float difference.
    SubF,
    /// Float product.
    MulF,
    /// Float quotient, 0 when dividing by 0.
    DivF,
    /// Smaller float.
    MinF,
    /// Larger float.
    MaxF,
    /// Absolute value.
    AbsF,
    /// Negation.
    NegF,
    /// Clamp to [min, max].
    ClampF,
    /// Sine of degrees.
    SinF,
    /// Cosine of degrees.
    CosF,
    /// Tangent of degrees.
    TanF,
    /// atan2 in degrees.
    Atan2F,
    /// Square root (0 for negatives).
    SqrtF,
    /// Power.
    PowF,
    /// Floored modulo.
    FmodF,
    /// Fractional part.
    FractF,
    /// Round down.
    FloorF,
    /// Round up.
    CeilF,
    /// Round to nearest.
    RoundF,
    /// Linear interpolation.
    LerpF,
    /// Linear remap.
    RemapF,
    /// Smooth Hermite step.
    SmoothStepF,
    /// Float → Int, truncating.
    ToInt,
    /// Int → Float.
    ToFloat,

    // ---- int ----
    /// Int sum (wrapping).
    AddI,
    /// Int difference (wrapping).
    SubI,
    /// Int product (wrapping).
    MulI,
    /// Int quotient, 0 when dividing by 0.
    DivI,
    /// Floored modulo, 0 for a zero divisor.
    ModI,
    /// Smaller int.
    MinI,
    /// Larger int.
    MaxI,
    /// Absolute value (wrapping).
    AbsI,
    /// Negation (wrapping).
    NegI,
    /// Clamp to [min, max].
    ClampI,

    // ---- bool and comparisons ----
    /// Logical and.
    And,
    /// Logical or.
    Or,
    /// Logical not.
    Not,
    /// Logical exclusive or.
    Xor,
    /// `a == b` for the given scalar type.
    Equals(Elem),
    /// `a != b` for the given scalar type.
    NotEquals(Elem),
    /// Float `a < b`.
    LessF,
    /// Float `a <= b`.
    LessEqualF,
    /// Float `a > b`.
    GreaterF,
    /// Float `a >= b`.
    GreaterEqualF,
    /// Int `a < b`.
    LessI,
    /// Int `a <= b`.
    LessEqualI,
    /// Int `a > b`.
    GreaterI,
    /// Int `a >= b`.
    GreaterEqualI,
    /// `[condition, if_true, if_false, result]` of the given type.
    Select(ValueType),

    // ---- vector ----
    /// Vector sum.
    AddV,
    /// Vector difference.
    SubV,
    /// Component-wise product.
    MulV,
    /// Component-wise quotient, 0 where the divisor is 0.
    DivV,
    /// Vector times float.
    ScaleV,
    /// Negation.
    NegV,
    /// Component-wise minimum.
    MinV,
    /// Component-wise maximum.
    MaxV,
    /// Component-wise absolute value.
    AbsV,
    /// Component-wise clamp.
    ClampV,
    /// Linear interpolation.
    LerpV,
    /// Length.
    LengthV,
    /// Distance between points.
    DistanceV,
    /// Unit vector, zero for a zero vector.
    UnitV,
    /// Dot product.
    DotV,
    /// Cross product.
    CrossV,
    /// `(x, y, z)` from floats.
    MakeVector,
    /// Floats from `(x, y, z)`.
    BreakVector,

    // ---- rotation ----
    /// Quaternion from axis and angle (degrees).
    QuatFromAxisAngle,
    /// Quaternion from Euler degrees and order.
    QuatFromEuler,
    /// Euler degrees from a quaternion and order.
    EulerFromQuat,
    /// Quaternion product (parent · child).
    MulQ,
    /// Inverse rotation.
    InverseQ,
    /// Normalised quaternion.
    UnitQ,
    /// Shortest-path spherical interpolation.
    SlerpQ,
    /// Rotate a vector.
    RotateVector,
    /// Scale a rotation's angle.
    QuatScale,
    /// Shortest rotation between two directions.
    FindQuatBetween,

    // ---- transform ----
    /// Transform from parts.
    MakeTransform,
    /// Parts of a transform.
    BreakTransform,
    /// Composition parent · child.
    MulT,
    /// Inverse transform.
    InverseT,
    /// `global` relative to `parent`.
    MakeRelative,
    /// `local` placed under `parent`.
    MakeAbsolute,
    /// Transform a point.
    TransformPoint,
    /// Transform a direction.
    TransformVector,
    /// Rotate a transform about a pivot.
    RotateAroundPoint,
    /// Lerp/slerp between transforms.
    InterpolateTransform,
    /// Aim an axis at a direction or point.
    AimMath,
    /// Align an axis with a normal.
    AlignToNormal,
    /// Position and tangent on a spline through points.
    Spline,
    /// Limit a vector's length.
    ClampLength,
    /// Keep a point within a spherical shell.
    ClampSpatially,

    // ---- hierarchy and host ----
    /// Read a bone transform.
    GetTransform,
    /// Write a bone transform.
    SetTransform,
    /// A bone's parent.
    GetParent,
    /// Descendants whose name matches.
    FindBones,
    /// Two-bone IK on a chain.
    TwoBoneIK,
    /// Seconds since the last frame.
    DeltaTime,
    /// Component-to-world transform of this frame.
    WorldTransform,

    /// Line trace against the host world.
    LineTrace,
    /// Sphere trace against the host world.
    SphereTrace,

    // ---- smoothing (use the frame's dt) ----
    /// Frame-rate independent exponential smoothing, float.
    FloatLerp,
    /// Frame-rate independent exponential smoothing, vector, optional max step.
    VectorLerp,
    /// Frame-rate independent exponential smoothing, rotation.
    QuatLerp,
    /// Unreal-style interp-to, float.
    FInterpToF,
    /// Unreal-style interp-to, vector.
    FInterpToV,
    /// Unreal-style interp-to, rotation.
    FInterpToQ,
    /// Critically damped spring, float (stateful).
    SpringF,
    /// Critically damped spring, vector (stateful).
    SpringV,

    // ---- locomotion units ----
    /// Movement-direction yaw offset with 8-direction folding.
    MovementAngleOffset,
    /// Per-foot yaw factor.
    PerFootRotationFactor,
    /// Clamp a rotation's yaw.
    LimitRotationAroundZ,
    /// Keep feet from crossing.
    FootAvoidance,
    /// Knee pole vector.
    KneeVector,
    /// Arm swing pitch.
    ArmSwingRotation,
    /// Clavicle bob.
    ClavicleOffset,
    /// Pelvis lean from velocity.
    PelvisLean,
    /// Pelvis roll from feet heights.
    PelvisSideLean,
    /// Heel, ball and tip pivots.
    FootPivots,
    /// Advance a cycle phase.
    CycleStep,
    /// Foot offset from a downward trace.
    FootOffsetFromTrace,
    /// Foot rotation from a ground normal.
    RotationFromNormal,

    // ---- arrays ----
    /// Element at an index.
    ArrayAt(Elem),
    /// Number of elements.
    ArrayCount(Elem),
    /// Overwrite an element of an array variable.
    ArraySetAt(Elem),
    /// Append to an array variable.
    ArrayAdd(Elem),
    /// Empty an array variable.
    ArrayReset(Elem),

    // ---- debug ----
    /// Draw a point.
    DrawPoint,
    /// Draw a line.
    DrawLine,
    /// Draw a transform's axes.
    DrawTransform,
    /// Draw an arrow.
    DrawArrow,
    /// Draw a sphere.
    DrawSphere,
    /// Draw a box.
    DrawBox,
    /// Draw a spline as a polyline.
    DrawSpline,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_op_fits_in_two_bytes() {
        // The executor's instruction is an `Op` plus a 32-bit operand offset; keep it at 8
        // bytes so a program stays dense in cache.
        assert!(std::mem::size_of::<Op>() <= 2);
    }
}
