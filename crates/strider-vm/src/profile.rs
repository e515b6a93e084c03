//! Per-instruction profiles and their aggregation per graph node.
//!
//! With the `profile` cargo feature, an [`Instance`](crate::Instance) whose profiling is
//! switched on (`Instance::set_profiling`, only in that build) accumulates,
//! for every instruction, the time spent in it and how many times it ran. The types here
//! are always available (a tool can be built either way); only the executor's timing is
//! behind the feature.

use crate::program::{InstrOrigin, OriginId, OriginKind, Program};

/// Whether this build of `strider-vm` has the `profile` feature (and so
/// `Instance::set_profiling`).
pub const PROFILING_AVAILABLE: bool = cfg!(feature = "profile");

/// Accumulated cost of one instruction.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct InstrProfile {
    /// Wall-clock time spent in the instruction, nanoseconds (measured with
    /// `std::time::Instant` between consecutive instructions, so it includes the dispatch
    /// and the timer's own cost; in a batch, between consecutive dispatches, each shared
    /// equally among the members at the instruction).
    pub nanos: u64,
    /// Times the instruction ran.
    pub count: u64,
}

/// Accumulated cost of one graph node or step: the sum over the instructions it produced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeProfile {
    /// The node or step ([`Program::origin`]); `None` for instructions without origin.
    pub origin: Option<OriginId>,
    /// Time spent in its instructions, nanoseconds (half of each fused instruction's, see
    /// [`Program::second_origin_id`]).
    pub nanos: u64,
    /// Times the node ran, summed over its copies (a function's nodes have one copy per
    /// call site): a node is one instruction, so the sum of their counts; for a call or a
    /// step, for each maximal run of consecutive instructions with this origin, the count
    /// of the first. Exact for nodes and calls; for a `ForEach`/`For` step the loop's back
    /// jump adds one per iteration, for a `Branch` the jump over `else` one per `then`.
    pub runs: u64,
    /// Instructions of it executed (sum of their counts; a fused instruction counts for
    /// both of its nodes).
    pub instructions: u64,
}

impl NodeProfile {
    /// The node's origin in `program`.
    #[must_use]
    pub fn origin<'p>(&self, program: &'p Program) -> Option<&'p InstrOrigin> {
        self.origin.map(|id| program.origin(id))
    }

    /// Mean time per run, nanoseconds (0 if it never ran).
    #[must_use]
    pub fn nanos_per_run(&self) -> f64 {
        if self.runs == 0 {
            0.0
        } else {
            self.nanos as f64 / self.runs as f64
        }
    }
}

/// Groups a per-instruction `profile` of `program` (indexed by instruction, as
/// `Instance::profile` returns it) by origin, i.e. per graph node or step; sorted by total
/// time, most expensive first (ties: most instructions executed, then origin order).
/// Entries that never ran are left out. Allocates: for tools, not for the frame loop.
#[must_use]
pub fn profile_by_node(program: &Program, profile: &[InstrProfile]) -> Vec<NodeProfile> {
    // Slot `origins.len()` collects instructions without origin.
    let none = program.origins().len();
    let mut acc: Vec<NodeProfile> = (0..=none)
        .map(|i| NodeProfile {
            origin: (i < none).then_some(OriginId(i as u32)),
            nanos: 0,
            runs: 0,
            instructions: 0,
        })
        .collect();
    let mut previous = None;
    for (pc, p) in profile.iter().enumerate() {
        let id = program.origin_id(pc);
        // A fused instruction runs two nodes' ops: its time is split evenly between them,
        // and each counts its runs and one instruction per run.
        let second = program.second_origin_id(pc);
        let mut nanos = p.nanos;
        if let Some(second) = second {
            let b = &mut acc[second.0 as usize];
            b.nanos += nanos - nanos / 2;
            b.instructions += p.count;
            b.runs += p.count;
            nanos /= 2;
        }
        let a = &mut acc[id.map_or(none, |id| id.0 as usize)];
        a.nanos += nanos;
        a.instructions += p.count;
        // A node is one instruction: each counts (two call sites of a function may leave
        // its nodes' instructions side by side once the copies between them are gone).
        let node = id.is_some_and(|id| program.origins()[id.0 as usize].kind == OriginKind::Node);
        if pc == 0 || id != previous || node {
            a.runs += p.count;
        }
        previous = second.or(id);
    }
    acc.retain(|a| a.instructions > 0);
    acc.sort_by(|a, b| {
        b.nanos
            .cmp(&a.nanos)
            .then(b.instructions.cmp(&a.instructions))
            .then(a.origin.cmp(&b.origin))
    });
    acc
}

#[cfg(all(test, feature = "profile"))]
mod tests {
    use super::*;
    use crate::{Event, FrameInput, Instance, OriginKind, OriginScope, ProgramBuilder};
    use std::sync::Arc;
    use strider_core::{Bone, EmptyWorld, Skeleton, Transform};
    use strider_nodes::{Op, Value, ValueType};

    const N: i32 = 7;

    /// `forward`: `For(count: N) { x = x + 1 }`, hand-built, with origins; `construction`:
    /// just `End`.
    fn loop_program() -> Program {
        let mut pb = ProgramBuilder::new("loop");
        let counter = pb.alloc(ValueType::Int);
        let index = pb.alloc(ValueType::Int);
        let n = pb.constant(&Value::Int(N), "");
        let zero = pb.constant(&Value::Int(0), "");
        let x = pb.alloc(ValueType::Float);
        let one = pb.constant(&Value::Float(1.0), "");
        let origin = |pb: &mut ProgramBuilder, ty: &str, kind| {
            pb.intern_origin(InstrOrigin {
                kind,
                node_id: (kind == OriginKind::Node).then(|| "inc".to_string()),
                node_type: ty.to_string(),
                scope: OriginScope::Event(Event::Forward),
                location: "loop.ron:3:5".to_string(),
            })
        };
        let looping = origin(&mut pb, "For", OriginKind::Step);
        let add = origin(&mut pb, "Add", OriginKind::Node);
        pb.set_forward_entry(pb.here());
        pb.set_origin(Some(looping));
        pb.emit(Op::Copy(ValueType::Int), &[zero, counter]);
        let head = pb.emit(Op::ForNext, &[counter, n, index, 0]);
        pb.set_origin(Some(add));
        pb.emit(Op::AddF, &[x, one, x]);
        pb.set_origin(Some(looping));
        pb.emit(Op::Jump, &[head]);
        let exit = pb.here();
        pb.patch(head, 3, exit);
        pb.set_origin(None);
        pb.emit(Op::End, &[]);
        pb.set_construction_entry(exit);
        pb.finish()
    }

    fn instance(program: Program) -> Instance {
        let skeleton = Skeleton::new(vec![Bone {
            name: "root".to_string(),
            parent: None,
            rest_local: Transform::IDENTITY,
        }])
        .expect("valid skeleton");
        Instance::new(Arc::new(program), Arc::new(skeleton)).expect("instantiates")
    }

    #[test]
    fn a_loop_body_is_counted_once_per_iteration() {
        let mut inst = instance(loop_program());
        let input = FrameInput::default();
        // Off: nothing is recorded (construction ran in `new`, before profiling was on).
        inst.run_forward(&input, &EmptyWorld, false);
        assert!(inst.profile().iter().all(|p| *p == InstrProfile::default()));
        assert!(!inst.is_profiling());

        inst.set_profiling(true);
        inst.run_forward(&input, &EmptyWorld, false);
        inst.run_forward(&input, &EmptyWorld, false);
        let counts: Vec<u64> = inst.profile().iter().map(|p| p.count).collect();
        // Copy, ForNext (N + 1 tests), AddF (N), Jump (N), End; two frames.
        let n = N as u64;
        assert_eq!(counts, vec![2, 2 * (n + 1), 2 * n, 2 * n, 2]);
        assert!(inst.profile()[2].nanos > 0, "time is measured");

        let nodes = inst.profile_by_node();
        let program = Arc::clone(inst.program());
        let add = nodes
            .iter()
            .find(|p| p.origin(&program).is_some_and(|o| o.label() == "inc"))
            .expect("the Add node is profiled");
        assert_eq!((add.runs, add.instructions), (2 * n, 2 * n));
        let looping = nodes
            .iter()
            .find(|p| p.origin(&program).is_some_and(|o| o.node_type == "For"))
            .expect("the loop is profiled");
        assert_eq!(looping.instructions, 2 + 2 * (n + 1) + 2 * n);
        // The End without origin is grouped apart.
        assert!(
            nodes
                .iter()
                .any(|p| p.origin.is_none() && p.instructions == 2)
        );
        let total: u64 = nodes.iter().map(|p| p.nanos).sum();
        let by_instr: u64 = inst.profile().iter().map(|p| p.nanos).sum();
        assert_eq!(total, by_instr);
        assert!(nodes.windows(2).all(|w| w[0].nanos >= w[1].nanos));

        inst.reset_profile();
        assert!(inst.profile().iter().all(|p| *p == InstrProfile::default()));
        inst.set_profiling(false);
        inst.run_forward(&input, &EmptyWorld, false);
        assert!(inst.profile().iter().all(|p| *p == InstrProfile::default()));
    }

    #[test]
    fn construction_is_profiled_too_and_rebind_keeps_the_profile() {
        let mut inst = instance(loop_program());
        inst.set_profiling(true);
        inst.run_construction(&EmptyWorld);
        assert_eq!(inst.profile()[4].count, 1, "construction's End");
        let skeleton = Arc::clone(inst.pose().skeleton());
        inst.rebind(skeleton, &EmptyWorld).expect("rebinds");
        assert!(inst.is_profiling());
        assert_eq!(inst.profile().len(), inst.program().code().len());
        assert_eq!(
            inst.profile()[4].count,
            2,
            "kept, and rebind's construction added"
        );
    }
}
