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

mod exec;
pub mod instance;
pub mod native;
pub mod profile;
pub mod program;
pub mod slots;

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
    fn an_instruction_is_eight_bytes() {
        // An op (2 bytes) and a 32-bit operand offset, padded: dense code keeps the
        // dispatch loop in cache.
        assert_eq!(std::mem::size_of::<Instr>(), 8);
    }
}
