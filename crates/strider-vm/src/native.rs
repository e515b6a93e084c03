//! Programs compiled ahead of time to Rust: the native baseline of the interpreter.
//!
//! [`generate`] turns a compiled [`Program`] into Rust source. The generated `forward`
//! function performs the program's forward event as straight-line calls of [`step`], one per
//! instruction, in program order, with the op and its operand slot indices written as
//! constants. [`step`] is always inlined and holds the same handlers as the interpreter, so
//! each call folds to one node kernel reading and writing the instance's slots at fixed
//! indices: the same kernels, the same data, the same order, without the dispatch loop, the
//! instruction fetch or the operand list. Control flow (branches and loops) becomes a
//! `match` over basic blocks. Outputs are bit-identical to the interpreter's.
//!
//! Generated code is tied to one program: it carries the program's [`fingerprint`], and
//! [`Instance::run_forward_native`](crate::Instance::run_forward_native) refuses code
//! generated from another program (a graph edited since, or a different compiler).
//!
//! This is what `strider bench` measures the interpreter against (`native_ratio`); the
//! `strider-native` crate holds the generated code of the shipped graphs.

use crate::exec::{self, Ctx};
use crate::program::{Instr, Program};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use strider_nodes::{Elem, MAX_OPERANDS, Op, ValueType};

/// One running event, as generated code sees it: the instance's slots, pose, debug buffer,
/// world and frame input. Made by [`Instance::run_forward_native`](crate::Instance::run_forward_native).
pub struct Frame<'a> {
    pub(crate) cx: Ctx<'a>,
}

/// Executes one instruction for generated code: `op` on the slots whose indices are
/// `operands` (laid out as [`Op`] documents), returning the index of the instruction to run
/// next — `next` unless the op jumps, [`usize::MAX`] after `End`.
///
/// Always inlined, so with a constant `op` and `operands` it compiles to that op's handler
/// alone.
///
/// # Safety
/// `op` and `operands` must be an instruction of the program `frame` runs, with its operands
/// as [`generate`] writes them: slot operands are then in bounds (the executor indexes scalar
/// slots unchecked; see [`ProgramBuilder::finish`](crate::ProgramBuilder::finish)). Frames
/// exist only inside [`Instance::run_forward_native`](crate::Instance::run_forward_native),
/// after it checked that the generated code's fingerprint is the program's.
#[inline(always)]
#[allow(unsafe_code)] // the unchecked executor's entry point for generated code
pub unsafe fn step(frame: &mut Frame<'_>, op: Op, operands: &[u32], next: usize) -> usize {
    // SAFETY: the caller's contract above is `exec::step`'s.
    unsafe { exec::step(op, operands, &mut frame.cx, next) }
}

/// A program's forward event compiled ahead of time (see the [module docs](self)).
#[derive(Clone, Copy, Debug)]
pub struct NativeProgram {
    /// The graph's name (the program's [`Program::name`] when generated).
    pub name: &'static str,
    /// The [`fingerprint`] of the program it was generated from.
    pub fingerprint: u64,
    /// The forward event.
    pub forward: fn(&mut Frame<'_>),
}

impl NativeProgram {
    /// Whether this code was generated from `program` (compares fingerprints; O(program
    /// size)).
    #[must_use]
    pub fn matches(&self, program: &Program) -> bool {
        fingerprint(program) == self.fingerprint
    }
}

/// A 64-bit fingerprint of a program's code: every instruction, every operand, both entry
/// points and the number of slots of each type. Equal programs have equal fingerprints on
/// every platform and build.
///
/// FNV-1a, written out here because std's hashers do not promise the same output across
/// Rust releases, and the fingerprint is stored in generated source files. Computed once
/// per program (O(program size)) and kept with it.
#[must_use]
pub fn fingerprint(program: &Program) -> u64 {
    *program
        .fingerprint
        .get_or_init(|| compute_fingerprint(program))
}

/// [`fingerprint`] itself, walking the whole program.
fn compute_fingerprint(program: &Program) -> u64 {
    const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01b3;
    let mut hash = OFFSET;
    let mut eat = |bytes: &[u8]| {
        for &b in bytes {
            hash ^= u64::from(b);
            hash = hash.wrapping_mul(PRIME);
        }
    };
    for Instr { op, args } in &program.code {
        eat(op_path(*op).as_bytes());
        eat(&args.to_le_bytes());
    }
    for o in &program.operands {
        eat(&o.to_le_bytes());
    }
    eat(&program.forward.to_le_bytes());
    eat(&program.construction.to_le_bytes());
    let s = &program.initial;
    for n in [
        s.bools.len(),
        s.ints.len(),
        s.floats.len(),
        s.vec3s.len(),
        s.quats.len(),
        s.transforms.len(),
        s.bones.len(),
        s.names.len(),
        s.bool_arrays.len(),
        s.int_arrays.len(),
        s.float_arrays.len(),
        s.vec3_arrays.len(),
        s.quat_arrays.len(),
        s.transform_arrays.len(),
        s.bone_arrays.len(),
    ] {
        eat(&(n as u64).to_le_bytes());
    }
    hash
}

/// The Rust expression of an op, for generated code that imports `Op`, `Elem` and
/// `ValueType` from `strider_nodes`.
fn op_path(op: Op) -> String {
    let elem = |e: Elem| format!("Elem::{e:?}");
    let ty = |t: ValueType| match t {
        ValueType::Array(e) => format!("ValueType::Array({})", elem(e)),
        t => format!("ValueType::{t:?}"),
    };
    match op {
        Op::ForEachNext(e) => format!("Op::ForEachNext({})", elem(e)),
        Op::Equals(e) => format!("Op::Equals({})", elem(e)),
        Op::NotEquals(e) => format!("Op::NotEquals({})", elem(e)),
        Op::ArrayAt(e) => format!("Op::ArrayAt({})", elem(e)),
        Op::ArrayCount(e) => format!("Op::ArrayCount({})", elem(e)),
        Op::ArraySetAt(e) => format!("Op::ArraySetAt({})", elem(e)),
        Op::ArrayAdd(e) => format!("Op::ArrayAdd({})", elem(e)),
        Op::ArrayReset(e) => format!("Op::ArrayReset({})", elem(e)),
        Op::Copy(t) => format!("Op::Copy({})", ty(t)),
        Op::Select(t) => format!("Op::Select({})", ty(t)),
        op => format!("Op::{op:?}"),
    }
}

/// Where control can go after instruction `pc` other than the next one, and whether it can
/// go to the next one at all.
fn successors(program: &Program, pc: usize) -> (Option<usize>, bool) {
    let Instr { op, args } = program.code[pc];
    let o = &program.operands[args as usize..];
    match op {
        Op::End => (None, false),
        Op::Jump => (Some(o[0] as usize), false),
        Op::JumpIfFalse => (Some(o[1] as usize), true),
        Op::ForEachNext(_) => (Some(o[5] as usize), true),
        Op::ForNext => (Some(o[3] as usize), true),
        _ => (None, true),
    }
}

/// The operands of instruction `pc`: the builder appends each instruction's operands after
/// the previous one's, so they run up to the next instruction's (for the last, up to the
/// padding at the end of the list).
fn instruction_operands(program: &Program, pc: usize) -> &[u32] {
    let start = program.code[pc].args as usize;
    let end = program.code.get(pc + 1).map_or(
        program.operands.len().saturating_sub(MAX_OPERANDS),
        |next| next.args as usize,
    );
    &program.operands[start..end.max(start)]
}

/// Generates the Rust source of `program`'s forward event (see the [module docs](self)):
/// a module-level `pub static NATIVE: NativeProgram` and the function it points to. `name`
/// is the graph's name as stored in the result; `header` is written first as `//!` lines
/// (what the file is and how to regenerate it).
#[must_use]
pub fn generate(program: &Program, name: &str, header: &str) -> String {
    // Basic blocks of the code reachable from the forward entry.
    let entry = program.forward as usize;
    let mut reachable = BTreeSet::new();
    let mut leaders = BTreeSet::from([entry]);
    let mut work = vec![entry];
    while let Some(pc) = work.pop() {
        if pc >= program.code.len() || !reachable.insert(pc) {
            continue;
        }
        let (jump, falls) = successors(program, pc);
        if let Some(target) = jump {
            leaders.insert(target);
            work.push(target);
        }
        if jump.is_some() || !falls {
            leaders.insert(pc + 1);
        }
        if falls {
            work.push(pc + 1);
        }
    }
    let mut blocks: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    let mut start = entry;
    for &pc in &reachable {
        // A reachable instruction that is not a leader is only reached by falling through
        // from the one before it, which is in the same block.
        if leaders.contains(&pc) {
            start = pc;
        }
        blocks.entry(start).or_default().push(pc);
    }

    let mut body = String::new();
    for (start, pcs) in &blocks {
        let _ = writeln!(body, "            {start} => {{");
        for (k, &pc) in pcs.iter().enumerate() {
            let Instr { op, .. } = program.code[pc];
            let operands = instruction_operands(program, pc)
                .iter()
                .map(u32::to_string)
                .collect::<Vec<_>>()
                .join(", ");
            let call = format!("step(f, {}, &[{operands}], {})", op_path(op), pc + 1);
            let (jump, falls) = successors(program, pc);
            if k + 1 < pcs.len() {
                let _ = writeln!(body, "                {call};");
            } else if jump.is_some() || !falls {
                // The block ends in a control op: it says where to go.
                let _ = writeln!(body, "                {call}");
            } else {
                // The block falls through into the next leader.
                let _ = writeln!(body, "                {call};\n                {}", pc + 1);
            }
        }
        let _ = writeln!(body, "            }}");
    }

    let mut out = String::new();
    for line in header.lines() {
        let _ = writeln!(out, "{}", format!("//! {line}").trim_end());
    }
    let types: Vec<&str> = ["Elem", "Op", "ValueType"]
        .into_iter()
        .filter(|t| body.contains(&format!("{t}::")))
        .collect();
    let _ = writeln!(out, "\nuse strider_nodes::{{{}}};", types.join(", "));
    let _ = writeln!(
        out,
        "use strider_vm::native::{{Frame, NativeProgram, step}};\n"
    );
    let _ = writeln!(
        out,
        "/// The forward event of `{name}`, compiled ahead of time."
    );
    let _ = writeln!(
        out,
        "pub static NATIVE: NativeProgram = NativeProgram {{\n    name: {name:?},\n    fingerprint: {:#018x},\n    forward,\n}};\n",
        fingerprint(program)
    );
    let _ = writeln!(out, "fn forward(f: &mut Frame<'_>) {{");
    let _ = writeln!(out, "    let mut pc: usize = {entry};");
    let _ = writeln!(out, "    loop {{");
    let _ = writeln!(
        out,
        "        // SAFETY: each `step` is an instruction of the program this code was generated\n        \
         // from, with its own operands; `NATIVE` runs only on that program (fingerprint)."
    );
    let _ = writeln!(out, "        pc = unsafe {{ match pc {{");
    out.push_str(&body);
    let _ = writeln!(out, "            _ => return,");
    let _ = writeln!(out, "        }} }};");
    let _ = writeln!(out, "    }}");
    let _ = writeln!(out, "}}");
    out
}
