//! Instruction origins (the compiler's source map, always on) and per-instruction
//! profiling (only with the `profile` feature: `cargo test --features profile --test
//! profile`). The zero-allocation check with profiling on is in `tests/allocations.rs`.

use std::path::Path;
use std::sync::Arc;
use strider_nodes::Op;
use strider_vm::{Event, OriginKind, OriginScope, Program};

const GRAPH: &str = r#"Graph(
    version: 1,
    name: "profiled",
    variables: {
        "N":   (type: Int, default: 5),
        "Acc": (type: Float),
        "Out": (type: Float),
        "Out2": (type: Float),
    },
    functions: {
        "Twice": (
            inputs:  { "x": Float },
            outputs: { "y": Float },
            nodes:   { "double": Multiply(a: "x", b: 2.0) },
            exec:    [ Return(y: "double") ],
        ),
    },
    nodes: {
        "acc_next": Add(a: var("Acc"), b: 1.0),
        "twice":    Twice(x: var("Acc")),
        "twice2":   Twice(x: 4.0),
    },
    events: {
        forward: [
            Set("Acc", 0.0),
            For(count: var("N"), index: "k", body: [
                Set("Acc", "acc_next"),
            ]),
            Set("Out", "twice"),
            Set("Out2", "twice2"),
        ],
    },
)
"#;

const PATH: &str = "tests/graphs/profiled.ron";

fn compile() -> Arc<Program> {
    match strider_compiler::compile_str(Path::new(PATH), GRAPH) {
        Ok(p) => Arc::new(p),
        Err(d) => panic!("{d:?}"),
    }
}

/// `PATH:line:` of the first line of `GRAPH` containing `text`.
fn line_of(text: &str) -> String {
    let line = GRAPH
        .lines()
        .position(|l| l.contains(text))
        .expect("text in graph")
        + 1;
    format!("{PATH}:{line}:")
}

/// The positions of the instructions running `op`.
fn pcs(program: &Program, op: Op) -> Vec<usize> {
    (0..program.code().len())
        .filter(|&pc| program.code()[pc].op == op)
        .collect()
}

#[test]
fn every_instruction_names_the_node_or_step_that_produced_it() {
    let program = compile();
    for pc in 0..program.code().len() {
        assert!(program.instruction_origin(pc).is_some(), "pc {pc}");
    }
    assert!(program.instruction_origin(program.code().len()).is_none());

    // The loop body's Add: a top-level node, emitted in forward.
    let add = pcs(&program, Op::AddF);
    assert_eq!(add.len(), 1);
    let o = program.instruction_origin(add[0]).unwrap();
    assert_eq!(o.kind, OriginKind::Node);
    assert_eq!(o.node_id.as_deref(), Some("acc_next"));
    assert_eq!(o.node_type, "Add");
    assert_eq!(o.scope, OriginScope::Event(Event::Forward));
    assert!(o.location.starts_with(&line_of("\"acc_next\"")), "{o}");

    // The Multiply inside the function: one copy per call site, one origin.
    let mul = pcs(&program, Op::MulF);
    assert_eq!(mul.len(), 2);
    assert_eq!(program.origin_id(mul[0]), program.origin_id(mul[1]));
    let o = program.instruction_origin(mul[0]).unwrap();
    assert_eq!(o.node_id.as_deref(), Some("double"));
    assert_eq!(o.node_type, "Multiply");
    assert_eq!(o.scope, OriginScope::Function("Twice".to_string()));
    assert!(o.location.starts_with(&line_of("\"double\"")), "{o}");
    assert_eq!(
        o.to_string(),
        format!("`double` (Multiply) in function `Twice` at {}", o.location)
    );

    // The loop test, the call's argument copies, the Set steps and the End.
    let o = program
        .instruction_origin(pcs(&program, Op::ForNext)[0])
        .unwrap();
    assert_eq!((o.kind, o.node_type.as_str()), (OriginKind::Step, "For"));
    assert!(o.location.starts_with(&line_of("For(count")), "{o}");
    // The argument copies into the call's input: compiled for tools (a slot per pin), as
    // shared slots let `Acc` be read where the input is (the copy goes).
    let graph = strider_graph::load_graph_str(Path::new(PATH), GRAPH.to_string()).unwrap();
    let options = strider_compiler::Options {
        keep_pin_values: true,
    };
    let kept = strider_compiler::compile_with(&graph, options).unwrap();
    let call = (0..kept.code().len())
        .filter_map(|pc| kept.instruction_origin(pc))
        .find(|o| o.kind == OriginKind::Call)
        .expect("the call has an origin");
    assert!(
        (0..program.code().len())
            .filter_map(|pc| program.instruction_origin(pc))
            .all(|o| o.kind != OriginKind::Call),
        "shared slots leave no argument copy"
    );
    assert_eq!(call.node_id.as_deref(), Some("twice"));
    assert_eq!(call.node_type, "Twice");
    let sets: Vec<&str> = program
        .origins()
        .iter()
        .filter(|o| o.node_type.starts_with("Set("))
        .map(|o| o.node_type.as_str())
        .collect();
    assert_eq!(
        sets,
        [
            "Set(\"Acc\")",
            "Set(\"Acc\")",
            "Set(\"Out\")",
            "Set(\"Out2\")"
        ]
    );
    let end = pcs(&program, Op::End);
    assert_eq!(
        program.instruction_origin(end[1]).unwrap().scope,
        OriginScope::Event(Event::Forward)
    );
}

#[test]
fn shipped_graphs_have_an_origin_with_a_location_for_every_instruction() {
    for path in [
        "graphs/foot_ik.ron",
        "graphs/pelvis_bob.ron",
        "tests/graphs/functions.ron",
        "tests/graphs/control_flow.ron",
    ] {
        let program = strider_compiler::compile_file(Path::new(path)).expect("compiles");
        for pc in 0..program.code().len() {
            let o = program
                .instruction_origin(pc)
                .unwrap_or_else(|| panic!("{path}: pc {pc} has no origin"));
            if o.node_type != "End" {
                assert!(!o.location.is_empty(), "{path}: pc {pc}: {o}");
            }
            if o.kind != OriginKind::Step {
                // Node origins point at the node's own file.
                assert!(o.location.contains(".ron:"), "{path}: {o}");
            }
        }
    }
}

#[cfg(feature = "profile")]
mod profiling {
    use super::*;
    use strider_core::EmptyWorld;
    use strider_nodes::Value;
    use strider_vm::{FrameInput, Instance};

    fn mannequin() -> Arc<strider_core::Skeleton> {
        strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
            .expect("mannequin loads")
            .skeleton
    }

    #[test]
    fn a_loop_body_runs_once_per_iteration() {
        let program = compile();
        let mut inst = Instance::new(Arc::clone(&program), mannequin()).expect("instantiates");
        let input = FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        };
        inst.set_profiling(true);
        inst.run_forward(&input, &EmptyWorld, false);
        let add = pcs(&program, Op::AddF)[0];
        assert_eq!(inst.profile()[add].count, 5);
        assert_eq!(inst.profile()[pcs(&program, Op::ForNext)[0]].count, 6);
        assert_eq!(inst.profile()[pcs(&program, Op::MulF)[0]].count, 1);

        let n = program.variable_id("N").unwrap();
        inst.set_variable(n, &Value::Int(9)).unwrap();
        inst.reset_profile();
        for _ in 0..3 {
            inst.run_forward(&input, &EmptyWorld, false);
        }
        assert_eq!(inst.profile()[add].count, 27);
        let out = program.variable_id("Out").unwrap();
        assert_eq!(inst.variable(out), Value::Float(18.0));

        let by_node = inst.profile_by_node();
        let acc = by_node
            .iter()
            .find(|p| p.origin(&program).and_then(|o| o.node_id.as_deref()) == Some("acc_next"))
            .expect("acc_next profiled");
        assert_eq!((acc.runs, acc.instructions), (27, 27));
        assert!(acc.nanos > 0);
        let double = by_node
            .iter()
            .find(|p| p.origin(&program).and_then(|o| o.node_id.as_deref()) == Some("double"))
            .expect("double profiled");
        // Two call sites, three frames.
        assert_eq!((double.runs, double.instructions), (6, 6));
        assert_eq!(
            inst.variable(program.variable_id("Out2").unwrap()),
            Value::Float(8.0)
        );
        assert!(by_node.windows(2).all(|w| w[0].nanos >= w[1].nanos));
    }

    #[test]
    fn foot_ik_profile_accounts_for_every_instruction_run() {
        let program =
            Arc::new(strider_compiler::compile_file(Path::new("graphs/foot_ik.ron")).unwrap());
        let mut inst = Instance::new(Arc::clone(&program), mannequin()).expect("instantiates");
        let input = FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        };
        inst.set_profiling(true);
        for _ in 0..10 {
            inst.run_forward(&input, &EmptyWorld, false);
        }
        let by_node = inst.profile_by_node();
        // A fused instruction counts for both of its nodes; its time is split between them.
        let executed: u64 = inst
            .profile()
            .iter()
            .zip(program.code())
            .map(|(p, i)| p.count * if i.op.fused_parts().is_some() { 2 } else { 1 })
            .sum();
        assert!(program.code().iter().any(|i| i.op.fused_parts().is_some()));
        assert_eq!(
            by_node.iter().map(|p| p.instructions).sum::<u64>(),
            executed
        );
        assert_eq!(
            by_node.iter().map(|p| p.nanos).sum::<u64>(),
            inst.profile().iter().map(|p| p.nanos).sum::<u64>()
        );
        // Every forward End ran once per frame; nothing of construction ran.
        let end = pcs(&program, Op::End);
        assert_eq!(inst.profile()[end[0]].count, 0);
        assert_eq!(inst.profile()[end[1]].count, 10);
        assert!(by_node.iter().all(|p| p.origin.is_some()));
    }

    #[test]
    fn a_profiling_instance_in_a_batch_runs_alone_and_is_profiled() {
        // `run_forward_batch` batches instances that profile only with each other: one
        // that profiles between two that do not runs by itself, its neighbours together,
        // all as they would alone.
        let program = compile();
        let make = || -> Vec<Instance> {
            (0..5)
                .map(|_| Instance::new(Arc::clone(&program), mannequin()).unwrap())
                .collect()
        };
        let (mut batched, mut alone) = (make(), make());
        batched[2].set_profiling(true);
        alone[2].set_profiling(true);
        let input = |_: usize| FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        };
        for _ in 0..3 {
            Instance::run_forward_batch(&mut batched, input, &EmptyWorld, false);
            for instance in &mut alone {
                instance.run_forward(&input(0), &EmptyWorld, false);
            }
        }
        let add = pcs(&program, Op::AddF)[0];
        // N = 5 rounds a frame, three frames.
        assert_eq!(batched[2].profile()[add].count, 15);
        assert_eq!(batched[1].profile()[add].count, 0, "not profiling");
        for (a, b) in batched.iter().zip(&alone) {
            assert!(a.slots().bit_eq(b.slots()));
        }
    }

    /// Each instruction's run count in `instances`' profiles, instance by instance.
    fn counts(instances: &[Instance]) -> Vec<Vec<u64>> {
        instances
            .iter()
            .map(|i| i.profile().iter().map(|p| p.count).collect())
            .collect()
    }

    #[test]
    fn profiling_instances_batched_together_count_what_each_runs_alone() {
        // Loops of different lengths split the batch and join it again; each member's
        // count of every instruction is what it runs alone, and the batch's time goes to
        // the instructions run.
        let program = compile();
        let n = program.variable_id("N").unwrap();
        let make = || -> Vec<Instance> {
            [3, 5, 0, 5, 8]
                .iter()
                .map(|&rounds| {
                    let mut i = Instance::new(Arc::clone(&program), mannequin()).unwrap();
                    i.set_variable(n, &Value::Int(rounds)).unwrap();
                    i.set_profiling(true);
                    i
                })
                .collect()
        };
        let (mut batched, mut alone) = (make(), make());
        let input = |_: usize| FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        };
        // How long the batched runs took, around them: the dispatches' times lie within.
        let mut wall = std::time::Duration::ZERO;
        for _ in 0..3 {
            let started = std::time::Instant::now();
            Instance::run_forward_batch(&mut batched, input, &EmptyWorld, false);
            wall += started.elapsed();
            for instance in &mut alone {
                instance.run_forward(&input(0), &EmptyWorld, false);
            }
        }
        assert_eq!(counts(&batched), counts(&alone));
        // Shared, not given to each member whole: all of them together took no longer than
        // the runs.
        let profiled: u64 = batched
            .iter()
            .flat_map(|i| i.profile().iter().map(|p| p.nanos))
            .sum();
        assert!(
            u128::from(profiled) <= wall.as_nanos(),
            "{profiled} ns in {wall:?}"
        );
        let add = pcs(&program, Op::AddF)[0];
        assert_eq!(
            batched[4].profile()[add].count,
            24,
            "8 rounds, three frames"
        );
        assert_eq!(batched[2].profile()[add].count, 0, "no rounds");
        assert!(batched[4].profile()[add].nanos > 0);
        // The batch ran them together: after the loops every member is at `Twice`'s
        // multiply with the others, and each dispatch's time is shared equally (the
        // remainder, under one nanosecond a member, to the first).
        for pc in pcs(&program, Op::MulF) {
            let nanos: Vec<u64> = batched.iter().map(|i| i.profile()[pc].nanos).collect();
            assert!(nanos[1..].iter().all(|&x| x == nanos[1]), "{nanos:?}");
            assert!(
                (nanos[1]..nanos[1] + 3 * 5).contains(&nanos[0]),
                "{nanos:?}"
            );
        }
        let end = pcs(&program, Op::End);
        for (a, b) in batched.iter().zip(&alone) {
            assert!(a.slots().bit_eq(b.slots()));
            // `End` counts as run, with no time of its own, as alone.
            assert_eq!(a.profile()[end[1]].count, 3);
            assert!(end.iter().all(|&pc| a.profile()[pc].nanos == 0));
        }
    }

    #[test]
    fn a_batched_locomotion_crowd_profiles_what_each_character_runs() {
        // The batch loop on lanes, with traces, the IK and branches that split the batch:
        // three characters at different points of a walk.
        let program =
            Arc::new(strider_compiler::compile_file(Path::new("graphs/locomotion.ron")).unwrap());
        let make = || -> Vec<Instance> {
            (0..3)
                .map(|_| {
                    let mut i = Instance::new(Arc::clone(&program), mannequin()).unwrap();
                    i.set_profiling(true);
                    i
                })
                .collect()
        };
        let (mut batched, mut alone) = (make(), make());
        let input = |k: usize, f: usize| FrameInput {
            dt: 1.0 / 60.0,
            component_to_world: strider_core::Transform::from_translation(glam::Vec3::new(
                0.0,
                (f * (k + 1)) as f32 * 4.0,
                0.0,
            )),
            ..Default::default()
        };
        for f in 0..12 {
            Instance::run_forward_batch(&mut batched, |k| input(k, f), &EmptyWorld, false);
            for (k, instance) in alone.iter_mut().enumerate() {
                instance.run_forward(&input(k, f), &EmptyWorld, false);
            }
        }
        assert_eq!(counts(&batched), counts(&alone));
        let ik = pcs(&program, Op::TwoBoneIK);
        assert!(!ik.is_empty());
        for instance in &batched {
            for &pc in &ik {
                // Each limb's IK, every frame.
                assert!(instance.profile()[pc].count >= 12);
                assert!(instance.profile()[pc].nanos > 0);
            }
        }
    }
}
