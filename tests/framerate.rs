//! Smoothing nodes are frame-rate independent: one second simulated at 30, 60, 144 and 240
//! Hz ends in the same place (within float rounding), while the Unreal-style FInterpTo —
//! kept for ported graphs — measurably does not.

use std::path::Path;
use std::sync::Arc;
use strider_core::EmptyWorld;
use strider_nodes::Value;
use strider_vm::{FrameInput, Instance};

/// Runs a graph that smooths variable `X` (Float) towards 100 with `node` (whose `current`
/// is `var("X")`), for one second at `hz`, and returns X.
fn after_one_second(node: &str, hz: u32) -> f32 {
    let text = format!(
        "Graph(version: 1, name: \"f\", variables: {{ \"X\": (type: Float) }}, nodes: {{ \"n\": {node} }}, events: {{ forward: [ Set(\"X\", \"n\") ] }})"
    );
    let program = Arc::new(strider_compiler::compile_str(Path::new("f.ron"), &text).unwrap());
    let skeleton = strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .unwrap()
        .skeleton;
    let mut instance = Instance::new(program.clone(), skeleton).unwrap();
    let dt = 1.0 / hz as f32;
    for _ in 0..hz {
        instance.run_forward(
            &FrameInput {
                dt,
                ..Default::default()
            },
            &EmptyWorld,
            false,
        );
    }
    match instance.variable(program.variable_id("X").unwrap()) {
        Value::Float(x) => x,
        v => panic!("{v:?}"),
    }
}

const RATES: [u32; 4] = [30, 60, 144, 240];

#[test]
fn exponential_smoothing_does_not_depend_on_the_frame_rate() {
    // 100·(1 − e^(−2·1 s)) = 86.4665 whatever the steps.
    let expected = 100.0 * (1.0 - (-2.0f32).exp());
    for hz in RATES {
        let x = after_one_second(
            "FloatLerp(current: var(\"X\"), target: 100.0, speed: 2.0)",
            hz,
        );
        assert!((x - expected).abs() < 2e-3, "{hz} Hz: {x} vs {expected}");
    }
}

#[test]
fn the_spring_matches_its_closed_form_at_every_frame_rate() {
    // The spring starts at rest on its first target, T = 0, and T jumps to 100 after the
    // first frame. A critically damped spring released from rest at distance j0 = −100
    // follows x(t) = 100 + (j0 + y·j0·t)·e^(−y·t), y = 2·ln 2 / half_life, for the
    // remaining t = 1 s − dt.
    let half_life = 0.3f32;
    let y = 2.0 * std::f32::consts::LN_2 / half_life;
    for hz in RATES {
        let text = "Graph(version: 1, name: \"s\", variables: { \"T\": (type: Float), \"X\": (type: Float) }, \
            nodes: { \"n\": SpringDamper(target: var(\"T\"), half_life: 0.3) }, \
            events: { forward: [ Set(\"X\", \"n\"), Set(\"T\", 100.0) ] })";
        let program = Arc::new(strider_compiler::compile_str(Path::new("s.ron"), text).unwrap());
        let skeleton = strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
            .unwrap()
            .skeleton;
        let mut instance = Instance::new(program.clone(), skeleton).unwrap();
        let dt = 1.0 / hz as f32;
        for _ in 0..hz {
            instance.run_forward(
                &FrameInput {
                    dt,
                    ..Default::default()
                },
                &EmptyWorld,
                false,
            );
        }
        let Value::Float(x) = instance.variable(program.variable_id("X").unwrap()) else {
            panic!()
        };
        let t = 1.0 - dt;
        let j0 = -100.0f32;
        let expected = 100.0 + (j0 + y * j0 * t) * (-y * t).exp();
        assert!((x - expected).abs() < 1e-3, "{hz} Hz: {x} vs {expected}");
    }
}

#[test]
fn finterp_to_depends_on_the_frame_rate() {
    // The seed's form 100·(1 − (1 − k·dt)^n) after 1 s at k = 2: 30 Hz gives
    // 100·(1 − (14/15)^30) = 87.376, 240 Hz gives 100·(1 − (119/120)^240) = 86.580.
    let at30 = after_one_second(
        "FInterpTo(current: var(\"X\"), target: 100.0, speed: 2.0)",
        30,
    );
    let at240 = after_one_second(
        "FInterpTo(current: var(\"X\"), target: 100.0, speed: 2.0)",
        240,
    );
    assert!((at30 - 87.376).abs() < 5e-3, "{at30}");
    assert!((at240 - 86.580).abs() < 5e-3, "{at240}");
}
