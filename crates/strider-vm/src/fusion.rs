//! Superinstructions: two adjacent instructions that often follow each other become one
//! fused instruction ([`Op::FUSED`]), which runs both handlers on their operand lists laid
//! end to end. The program does the same work with one dispatch (fetch, decode, jump)
//! fewer per pair, and a fused transform read passes the transform on without storing it
//! and loading it again in between.
//!
//! A pair fuses when the second instruction is not the start of a basic block (no jump
//! lands on it, no event starts there), so control can only reach it from the first, and
//! when its operands follow the first's in the operand list (the compiler emits them that
//! way). Both instructions write everything they wrote before, in the same order: the
//! results are bit-identical, and nothing else in the program changes but the jump targets
//! past a removed instruction.

use crate::program::{NO_ORIGIN, Program};
use crate::sharing::{Layouts, leaders, remove_instructions};
use fixedbitset::FixedBitSet;
use strider_nodes::Op;

/// Fuses every pair of adjacent instructions that has a fused op, left to right; the
/// second instruction of a pair is removed and its origin kept as the fused instruction's
/// second origin ([`Program::second_origin_id`]). `layouts` are the instructions' operand
/// layouts, kept in step (a fused instruction's is its op's).
pub(crate) fn fuse(program: &mut Program, layouts: &mut Layouts) {
    let n = program.code.len();
    debug_assert_eq!(layouts.len(), n, "a layout per instruction");
    // A fused op never jumps, so a pair's second instruction starts a block only when
    // something jumps to it or an event starts there.
    let leader = leaders(program, layouts);
    let mut dropped = FixedBitSet::with_capacity(n);
    program.second_origins = vec![NO_ORIGIN; n];
    let mut pc = 0;
    while pc + 1 < n {
        let (first, second) = (program.code[pc], program.code[pc + 1]);
        let fused = Op::FUSED
            .into_iter()
            .find(|&(_, parts)| parts == (first.op, second.op));
        let contiguous = second.args as usize == first.args as usize + layouts[pc].len();
        match fused {
            Some((op, _)) if contiguous && !leader.contains(pc + 1) => {
                program.code[pc].op = op;
                layouts[pc] = op.operands().unwrap_or_default();
                program.second_origins[pc] = program.instr_origins[pc + 1];
                dropped.insert(pc + 1);
                pc += 2;
            }
            _ => pc += 1,
        }
    }
    remove_instructions(program, layouts, &dropped);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sharing::layouts;
    use crate::{EmptyWorld, FrameInput, Instance, ProgramBuilder};
    use std::sync::Arc;
    use strider_core::{Bone, Skeleton, Transform};
    use strider_nodes::{Operand, Value, ValueType};

    /// `forward`, by hand (slots named as in the comments; `a = 2, b = 3, c = 4`):
    ///
    /// ```text
    /// 0  MulF a b x          x = 6          ┐ fused
    /// 1  AddF x c y          y = 10         ┘
    /// 2  SubF y a z          z = 8          ┐ fused
    /// 3  MulF z z w          w = 64         ┘
    /// 4  JumpIfFalse flag 6
    /// 5  MulF w b u          u = 192        not fused: a jump lands on 6
    /// 6  AddF u c r          r = u + 4
    /// 7  End
    /// ```
    ///
    /// Returns the program (built without sharing, so the slots keep their numbers) and the
    /// float slots of `x`, `y`, `z`, `w`, `u`, `r`.
    fn program(flag: bool) -> (Program, [usize; 6]) {
        let mut pb = ProgramBuilder::new("pairs");
        let [a, b, c] = [2.0, 3.0, 4.0].map(|v| pb.constant(&Value::Float(v), ""));
        let flag = pb.constant(&Value::Bool(flag), "");
        let [x, y, z, w, u, r] = [(); 6].map(|()| pb.alloc(ValueType::Float));
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::MulF, &[a, b, x]);
        pb.emit(Op::AddF, &[x, c, y]);
        pb.emit(Op::SubF, &[y, a, z]);
        pb.emit(Op::MulF, &[z, z, w]);
        let branch = pb.emit(Op::JumpIfFalse, &[flag, 0]);
        pb.emit(Op::MulF, &[w, b, u]);
        let join = pb.emit(Op::AddF, &[u, c, r]);
        pb.patch(branch, 1, join);
        pb.emit(Op::End, &[]);
        (pb.finish(), [x, y, z, w, u, r].map(|s| s as usize))
    }

    fn run(program: Program) -> crate::Slots {
        let skeleton = Skeleton::new(vec![Bone {
            name: "root".to_string(),
            parent: None,
            rest_local: Transform::IDENTITY,
        }])
        .expect("valid skeleton");
        let mut instance =
            Instance::new(Arc::new(program), Arc::new(skeleton)).expect("instantiates");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        instance.slots().clone()
    }

    #[test]
    fn adjacent_pairs_fuse_unless_a_jump_lands_between() {
        for flag in [true, false] {
            let (plain, [x, y, z, w, u, r]) = program(flag);
            let mut fused = plain.clone();
            let mut shapes = layouts(&fused);
            fuse(&mut fused, &mut shapes);
            let ops: Vec<Op> = fused.code().iter().map(|i| i.op).collect();
            let forward = fused.forward as usize;
            assert_eq!(
                ops[forward..],
                [
                    Op::MulFAddF,
                    Op::SubFMulF,
                    Op::JumpIfFalse,
                    Op::MulF,
                    Op::AddF,
                    Op::End
                ]
            );
            // The branch now lands on the AddF two instructions earlier.
            let branch = &fused.code()[forward + 2];
            assert_eq!(
                fused.operands()[branch.args as usize + 1],
                forward as u32 + 4
            );

            let floats = run(fused).floats;
            assert_eq!(floats, run(plain).floats, "same results, bit for bit");
            let u_value = if flag { 192.0 } else { 0.0 };
            let expected = [6.0, 10.0, 8.0, 64.0, u_value, u_value + 4.0];
            for (slot, value) in [x, y, z, w, u, r].into_iter().zip(expected) {
                assert_eq!(floats[slot], value, "slot {slot} with flag {flag}");
            }
        }
    }

    #[test]
    fn a_fused_instruction_keeps_both_origins() {
        use crate::{Event, InstrOrigin, OriginKind, OriginScope};
        let mut pb = ProgramBuilder::new("origins");
        let two = pb.constant(&Value::Float(2.0), "");
        let [x, y] = [(); 2].map(|()| pb.alloc(ValueType::Float));
        let node = |pb: &mut ProgramBuilder, id: &str| {
            pb.intern_origin(InstrOrigin {
                kind: OriginKind::Node,
                node_id: Some(id.to_string()),
                node_type: "Multiply".to_string(),
                scope: OriginScope::Event(Event::Forward),
                location: String::new(),
            })
        };
        let (first, second) = (node(&mut pb, "first"), node(&mut pb, "second"));
        pb.set_forward_entry(pb.here());
        pb.set_origin(Some(first));
        pb.emit(Op::MulF, &[two, two, x]);
        pb.set_origin(Some(second));
        pb.emit(Op::MulF, &[x, two, y]);
        pb.set_origin(None);
        pb.emit(Op::End, &[]);
        let mut program = pb.finish();
        let mut shapes = layouts(&program);
        fuse(&mut program, &mut shapes);
        assert_eq!(program.code()[0].op, Op::MulFMulF);
        assert_eq!(program.origin_id(0), Some(first));
        assert_eq!(program.second_origin_id(0), Some(second));
        assert_eq!(program.second_origin_id(1), None);
        assert_eq!(program.origin_id(1), None, "the End");
    }

    #[test]
    fn every_fused_op_lays_out_and_runs_both_parts() {
        for (op, (first, second)) in Op::FUSED {
            assert_eq!(op.fused_parts(), Some((first, second)));
            assert_eq!((first.fused_parts(), second.fused_parts()), (None, None));
            let mut both = first.operands().expect("a layout").into_owned();
            let first_len = both.len();
            both.extend_from_slice(&second.operands().expect("a layout"));
            assert_eq!(op.operands().as_deref(), Some(both.as_slice()), "{op:?}");
            assert!(both.len() <= strider_nodes::MAX_OPERANDS, "{op:?}");

            // The two ops, then the fused op, on the same slots: inputs with distinct
            // values, the second op reading the first's results where the types allow.
            let mut pb = ProgramBuilder::new("parts");
            let mut seed = 1.0f32;
            let mut slots: Vec<u32> = both
                .iter()
                .map(|operand| {
                    seed += 1.5;
                    match *operand {
                        Operand::Slot(ValueType::Float, _) => pb.constant(&Value::Float(seed), ""),
                        Operand::Slot(ValueType::Vec3, _) => {
                            pb.constant(&Value::Vec3(glam::Vec3::new(seed, -seed, 0.5 * seed)), "")
                        }
                        Operand::Slot(ty, _) => pb.alloc(ty),
                        Operand::Target => unreachable!("no fused op jumps"),
                    }
                })
                .collect();
            // The first op's result (its last operand) feeds the second op's first operand
            // of the same type, as in the pairs the pass finds.
            let ty = |k: usize| match both[k] {
                Operand::Slot(ty, _) => Some(ty),
                Operand::Target => None,
            };
            let result = first_len - 1;
            if let Some(k) = (first_len..both.len()).find(|&k| ty(k) == ty(result)) {
                slots[k] = slots[result];
            }
            pb.set_construction_entry(pb.here());
            pb.emit(Op::End, &[]);
            pb.set_forward_entry(pb.here());
            pb.emit(first, &slots[..first_len]);
            pb.emit(second, &slots[first_len..]);
            pb.emit(Op::End, &[]);
            let plain = pb.finish();
            let mut fused = plain.clone();
            let mut shapes = layouts(&fused);
            fuse(&mut fused, &mut shapes);
            assert_eq!(fused.code()[fused.forward as usize].op, op);
            // Debug prints each float as the shortest text that reads back to its bits.
            let (a, b) = (run(plain), run(fused));
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "{op:?}");
        }
    }
}
