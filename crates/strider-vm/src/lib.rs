//! The Strider runtime: an immutable [`Program`] shared by any number of per-character
//! [`Instance`]s, and the executor that runs a program's events on an instance.
//!
//! # Evaluation model
//!
//! ```text
//!   Program (Send + Sync, shared)            Instance (one per character)
//!   ┌───────────────────────────────┐        ┌──────────────────────────────┐
//!   │ code: [Instr]  ── entry points│        │ slots: typed memory (vars,   │
//!   │ operands: [u32] slot indices  │  run → │        node outputs, consts) │
//!   │ initial slots (consts, vars)  │        │ pose: locals + lazy globals  │
//!   │ variables, bone names         │        │ debug-draw buffer            │
//!   └───────────────────────────────┘        └──────────────────────────────┘
//! ```
//!
//! A program is a flat list of instructions in execution order. Each instruction is an
//! [`Op`](strider_nodes::Op) and an offset into the operand list, whose entries index the
//! instance's typed slot arrays (one array per value type). The executor is a `match` loop
//! over ops: no allocation, no string or hash lookup, no dynamic dispatch per pin.
//! Bones named in the graph are resolved to indices when an instance is created.
//!
//! Programs are built by the compiler (`strider-compiler`), which guarantees what the
//! executor trusts: operand counts and slot types match the op.

mod array_lanes;
mod batch_code;
mod exec;
mod fusion;
pub mod instance;
mod lanes;
pub mod native;
mod per_member;
mod prefetch;
pub mod profile;
pub mod program;
mod sharing;
pub mod slots;
mod transpose;

pub use batch_code::{BatchCode, allow_avx2, batch_code};
pub use exec::BATCH;
pub use instance::{
    FrameInput, InputPose, Instance, InstantiateError, MissingBone, NativeMismatch, VariableError,
};
pub use profile::{InstrProfile, NodeProfile, PROFILING_AVAILABLE, profile_by_node};
pub use program::{
    BoneLiteral, BoneSlot, Event, Instr, InstrOrigin, OriginId, OriginKind, OriginScope, PinOwner,
    PinSlot, Program, ProgramBuilder, VariableId, VariableInfo,
};
pub use slots::Slots;
pub use strider_core::{DebugDraw, EmptyWorld, TraceHit, WorldQuery};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn programs_are_shareable_across_threads() {
        fn assert_send_sync<T: Send + Sync>() {}
        assert_send_sync::<Program>();
        assert_send_sync::<std::sync::Arc<Program>>();
    }

    #[test]
    fn slot_operands_past_the_end_get_slots() {
        // Scalar slots are indexed unchecked: `finish` must give every slot operand a slot,
        // even one a hand-built program names without allocating it.
        use strider_nodes::{Op, Value};
        let mut pb = ProgramBuilder::new("past_the_end");
        let two = pb.constant(&Value::Float(2.0), "");
        let three = pb.constant(&Value::Float(3.0), "");
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::AddF, &[two, three, 40]); // float slot 40 was never allocated
        pb.emit(Op::MakeVector, &[two, three, 40, 9]); // nor vector slot 9
        pb.emit(Op::End, &[]);
        let program = pb.finish();
        assert_eq!(program.initial_slots().floats.len(), 41);
        assert_eq!(program.initial_slots().vec3s.len(), 10);
        let mut instance =
            Instance::new(std::sync::Arc::new(program), one_bone()).expect("instantiates");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        assert_eq!(instance.slots().floats[40], 5.0);
        assert_eq!(instance.slots().vec3s[9], glam::Vec3::new(2.0, 3.0, 5.0));
    }

    /// Every op a program can hold: the node table's, the fused pairs, and the control,
    /// copy and conversion ops the compiler emits, of every type.
    pub(crate) fn every_op() -> Vec<strider_nodes::Op> {
        use strider_nodes::{Elem, Op, ValueType};
        let mut ops: Vec<Op> = strider_nodes::registry()
            .nodes()
            .iter()
            .flat_map(|n| n.overloads.iter().map(|o| o.op))
            .chain(Op::FUSED.map(|(fused, _)| fused))
            .chain([
                Op::End,
                Op::Jump,
                Op::JumpIfFalse,
                Op::ForNext,
                Op::IntToFloat,
            ])
            .chain(Elem::ALL.map(Op::ForEachNext))
            .chain(
                ValueType::ALL
                    .iter()
                    .flat_map(|&t| [Op::Copy(t), Op::Select(t)]),
            )
            .collect();
        ops.sort_by_key(|op| format!("{op:?}"));
        ops.dedup();
        ops
    }

    /// A skeleton of one bone at the origin (the executor's tests use it too).
    pub(crate) fn one_bone() -> std::sync::Arc<strider_core::Skeleton> {
        use strider_core::{Bone, Skeleton, Transform};
        std::sync::Arc::new(
            Skeleton::new(vec![Bone {
                name: "root".to_string(),
                parent: None,
                rest_local: Transform::IDENTITY,
            }])
            .expect("valid skeleton"),
        )
    }

    #[test]
    fn a_program_that_could_run_past_its_end_gets_an_end() {
        // Instructions are fetched unchecked: `finish` must end every program with an
        // instruction that cannot fall through, including an empty one.
        use strider_nodes::{Op, Value};
        let empty = ProgramBuilder::new("empty").finish();
        assert_eq!(empty.code().len(), 1);
        assert_eq!(empty.code()[0].op, Op::End);

        let mut pb = ProgramBuilder::new("falls_through");
        let two = pb.constant(&Value::Float(2.0), "");
        let sum = pb.alloc(strider_nodes::ValueType::Float);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::AddF, &[two, two, sum]);
        let program = pb.finish();
        assert_eq!(program.code().len(), 2);
        assert_eq!(program.code()[1].op, Op::End);
        let mut instance =
            Instance::new(std::sync::Arc::new(program), one_bone()).expect("instantiates");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        assert_eq!(instance.slots().floats[sum as usize], 4.0);

        // A program already ending in `End` or `Jump` is left as it is.
        let mut pb = ProgramBuilder::new("ends");
        pb.emit(Op::Jump, &[0]);
        assert_eq!(pb.finish().code().len(), 1);
    }

    #[test]
    #[should_panic(expected = "jumps to 7, past the 2 instructions")]
    fn a_jump_past_the_end_is_refused() {
        use strider_nodes::Op;
        let mut pb = ProgramBuilder::new("bad_jump");
        pb.emit(Op::Jump, &[7]);
        pb.emit(Op::End, &[]);
        let _ = pb.finish();
    }

    #[test]
    #[should_panic(expected = "names array variable 7 of Int, which the program does not have")]
    fn an_array_the_program_lacks_is_refused() {
        use strider_nodes::{Elem, Op, ValueType};
        let mut pb = ProgramBuilder::new("bad_array");
        let (index, out) = (pb.alloc(ValueType::Int), pb.alloc(ValueType::Int));
        let _ = pb.alloc(ValueType::Array(Elem::Int));
        pb.emit(Op::ArrayAt(Elem::Int), &[7, index, out]);
        pb.emit(Op::End, &[]);
        let _ = pb.finish();
    }

    #[test]
    #[should_panic(expected = "the forward entry 5 is not one of the 1 instructions")]
    fn an_entry_past_the_end_is_refused() {
        let mut pb = ProgramBuilder::new("bad_entry");
        pb.set_forward_entry(5);
        let _ = pb.finish();
    }

    #[test]
    fn slot_bit_equality_sees_arrays_and_signs() {
        let a = Slots {
            floats: vec![0.0, f32::NAN],
            vec3_arrays: vec![vec![glam::Vec3::ONE]],
            ..Slots::default()
        };
        let mut b = a.clone();
        assert!(a.bit_eq(&b));
        b.vec3_arrays[0][0].z = 2.0;
        assert!(!a.bit_eq(&b));
        let mut c = a.clone();
        c.floats[0] = -0.0;
        assert!(!a.bit_eq(&c));
    }

    #[test]
    fn an_instruction_is_eight_bytes() {
        // An op (2 bytes) and a 32-bit operand offset, padded: dense code keeps the
        // dispatch loop in cache.
        assert_eq!(std::mem::size_of::<Instr>(), 8);
    }
}
