//! The node library: one table that defines every built-in node (its pins, types,
//! defaults, units and docs), the instruction set those nodes compile to, and the kernels
//! that do their math.
//!
//! This crate knows nothing of the VM, of files or of serde. The compiler reads the
//! [`registry`] to type-check graphs and pick an [`Op`] per node; the VM's executor
//! matches on [`Op`] and calls the kernels in [`kernels`]; `strider nodes` and
//! `docs/nodes.md` print the same table.
//!
//! Conventions are those of [`strider_core`]: rig space +Z up, +Y forward, +X left,
//! centimetres, degrees on every pin.

pub mod kernels;
pub mod ops;
pub mod table;
pub mod types;

pub use ops::{Access, MAX_OPERANDS, Op, Operand};
pub use table::{Effect, NodeSpec, Overload, PinSpec, Registry, registry};
pub use types::{Elem, Value, ValueType};
