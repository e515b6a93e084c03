//! Runs one op `REPS` times per frame on a batch of 16 instances, for `FRAMES` frames, so
//! that an instruction counter can price it per character.
//!
//! ```text
//! cargo build --release -p strider-vm --example op_cost
//! valgrind --tool=callgrind --toggle-collect='strider_vm::instance::Instance::run_forward_batch' \
//!     target/release/examples/op_cost OP REPS FRAMES [baseline]
//! ```
//!
//! With `baseline` the batches run the baseline x86-64 copy of the batch loop, not the
//! AVX2 one (`strider_vm::allow_avx2`).
//!
//! `OP` is the op's `Debug` name (`AddF`, `Select(Float)`, `RotateAroundPoint`, ...). The
//! instructions of a run with 400 reps minus those of a run with 200, divided by
//! `200 · 16 · FRAMES`, are the op's cost per character on the lanes (dispatch included);
//! docs/performance.md lists them for the locomotion graph's most frequent ops. Every
//! member gets the same inputs (one value per type), so kernels that reuse a result for
//! equal inputs show their best case.

use std::sync::Arc;
use strider_core::{Bone, Skeleton, Transform};
use strider_nodes::{Access, Op, Operand, Value, ValueType};
use strider_vm::{EmptyWorld, FrameInput, Instance, ProgramBuilder};

/// An ordinary input value of `ty`.
fn input(ty: ValueType) -> Value {
    match ty {
        ValueType::Bool => Value::Bool(true),
        ValueType::Int => Value::Int(3),
        ValueType::Float => Value::Float(1.25),
        ValueType::Vec3 => Value::Vec3(glam::Vec3::new(1.0, 2.0, 3.0)),
        ValueType::Quat => Value::Quat(glam::Quat::from_rotation_z(0.3)),
        ValueType::Transform => {
            Value::Transform(Transform::from_translation(glam::Vec3::new(1.0, 2.0, 3.0)))
        }
        _ => Value::Int(0),
    }
}

fn main() -> Result<(), String> {
    let mut args = std::env::args().skip(1);
    let usage = "usage: op_cost OP [REPS] [FRAMES] [baseline]";
    let name = args.next().ok_or(usage)?;
    let number = |arg: Option<String>, default: usize| {
        arg.map_or(Ok(default), |s| {
            s.parse::<usize>().map_err(|e| format!("{s}: {e}"))
        })
    };
    let reps = number(args.next(), 200)?;
    let frames = number(args.next(), 10)?;
    match args.next().as_deref() {
        None => {}
        Some("baseline") => strider_vm::allow_avx2(false),
        Some(other) => return Err(format!("{other}: expected `baseline`; {usage}")),
    }
    let op = strider_nodes::registry()
        .nodes()
        .iter()
        .flat_map(|n| n.overloads.iter().map(|o| o.op))
        .chain(Op::FUSED.map(|(fused, _)| fused))
        .chain(
            ValueType::ALL
                .iter()
                .flat_map(|&t| [Op::Copy(t), Op::Select(t)]),
        )
        .find(|op| format!("{op:?}") == name)
        .ok_or_else(|| format!("no op named {name}"))?;
    let layout = op
        .operands()
        .ok_or_else(|| format!("{name} has no layout"))?;

    // One slot per operand, inputs holding ordinary values; every copy of the op reads and
    // writes the same slots (so the program has far more instructions than slots and runs
    // on the lanes).
    let mut pb = ProgramBuilder::new("op_cost");
    pb.set_construction_entry(pb.here());
    pb.emit(Op::End, &[]);
    pb.set_forward_entry(pb.here());
    let operands: Vec<u32> = layout
        .iter()
        .map(|operand| match *operand {
            Operand::Slot(ty, Access::Read) => {
                let slot = pb.alloc(ty);
                pb.write(slot, &input(ty), "");
                slot
            }
            Operand::Slot(ty, _) => pb.alloc(ty),
            Operand::Target => 0,
        })
        .collect();
    for _ in 0..reps {
        pb.emit(op, &operands);
    }
    pb.emit(Op::End, &[]);
    let program = Arc::new(pb.finish());
    let root = Bone {
        name: "root".into(),
        parent: None,
        rest_local: Transform::IDENTITY,
    };
    let skeleton = Arc::new(Skeleton::new(vec![root]).map_err(|e| format!("{e:?}"))?);
    let mut crowd = (0..16)
        .map(|_| Instance::new(program.clone(), skeleton.clone()))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    let input = FrameInput {
        dt: 1.0 / 60.0,
        ..FrameInput::default()
    };
    for _ in 0..frames {
        Instance::run_forward_batch(&mut crowd, |_| input, &EmptyWorld, false);
    }
    Ok(())
}
