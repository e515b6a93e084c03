//! Regression: the checker and code generator walk data-flow chains without recursion,
//! so a very long chain compiles instead of overflowing the stack (it once did at about
//! 10 000 nodes, through a recursive strongly-connected-components search).

use std::path::Path;

fn chain(n: usize, close_cycle: bool) -> String {
    let mut text = String::from(
        "Graph(version: 1, name: \"chain\", variables: { \"Out\": (type: Float) }, nodes: {\n",
    );
    let first = if close_cycle {
        format!("\"n{}\"", n - 1)
    } else {
        "1.0".to_string()
    };
    text.push_str(&format!("\"n0\": Add(a: {first}, b: 1.0),\n"));
    for i in 1..n {
        text.push_str(&format!("\"n{i}\": Add(a: \"n{}\", b: 1.0),\n", i - 1));
    }
    text.push_str(&format!(
        "}}, events: {{ forward: [ Set(\"Out\", \"n{}\") ] }})",
        n - 1
    ));
    text
}

#[test]
fn a_long_chain_compiles_and_computes() {
    let n = 50_000;
    let program = strider_compiler::compile_str(Path::new("chain.ron"), &chain(n, false)).unwrap();
    // One Add per node (two in a fused instruction), then the Set's copy and the event
    // ends.
    let ops: usize = program
        .code()
        .iter()
        .map(|i| if i.op.fused_parts().is_some() { 2 } else { 1 })
        .sum();
    assert!(ops >= n);
}

#[test]
fn a_long_cycle_is_reported_once() {
    let errors =
        strider_compiler::compile_str(Path::new("cycle.ron"), &chain(20_000, true)).unwrap_err();
    // The middle of the path, n6 ..= n19997, is 19 992 nodes.
    assert_eq!(errors.len(), 1, "{:?}", errors.first());
    assert_eq!(
        errors[0].message,
        "data-flow cycle: n0 → n1 → n2 → n3 → n4 → n5 → … (19992 more) → n19998 → n19999 → n0"
    );
}
