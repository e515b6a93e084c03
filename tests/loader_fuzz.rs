//! Property tests: whatever text it is given, the graph compiler
//! (`strider_compiler::compile_str`) and the skeleton loader
//! (`strider_graph::load_skeleton_str`) return `Ok` or `Err` — they never panic.
//!
//! Inputs: random bytes, random soups of RON-ish tokens, truncations and single-byte
//! mutations of every shipped graph and skeleton file, and randomly generated graphs built
//! from the real node table (which mostly type-check, so they reach the checker and code
//! generator; those that compile are also instantiated and run for a few frames, which must
//! not panic either). Case counts are modest so the file runs in a few seconds in debug.

use proptest::prelude::*;
use proptest::test_runner::Config;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};
use strider_core::{EmptyWorld, Skeleton};
use strider_host::scenario::Scenario;
use strider_nodes::{Effect, ValueType, registry};
use strider_vm::{FrameInput, Instance};

// ---------------------------------------------------------------------------------------
// Corpus and helpers
// ---------------------------------------------------------------------------------------

/// Every `.ron` file under `dir`, recursively, sorted.
fn ron_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            ron_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "ron") {
            out.push(path);
        }
    }
}

/// The shipped files (`graphs/**/*.ron`) and this suite's own graphs (`tests/graphs`),
/// with their text.
fn corpus() -> &'static [(PathBuf, String)] {
    static CORPUS: OnceLock<Vec<(PathBuf, String)>> = OnceLock::new();
    CORPUS.get_or_init(|| {
        let mut files = Vec::new();
        ron_files(Path::new("graphs"), &mut files);
        ron_files(Path::new("tests/graphs"), &mut files);
        files.sort();
        files
            .into_iter()
            .map(|p| {
                let text = std::fs::read_to_string(&p).unwrap();
                (p, text)
            })
            .collect()
    })
}

fn mannequin() -> Arc<Skeleton> {
    static SKELETON: OnceLock<Arc<Skeleton>> = OnceLock::new();
    Arc::clone(SKELETON.get_or_init(|| {
        strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
            .unwrap_or_else(|_| panic!("mannequin loads"))
            .skeleton
    }))
}

/// Feeds `text` to every loader (graph, skeleton, scenario), as if it were the file at
/// `path`. Returns whether the graph compiled. Any panic fails the test with the input
/// shown.
fn load_both(path: &Path, text: &str) -> bool {
    let graph = catch_unwind(AssertUnwindSafe(|| {
        strider_compiler::compile_str(path, text).is_ok()
    }));
    let skeleton = catch_unwind(AssertUnwindSafe(|| {
        let _ = strider_graph::load_skeleton_str(path, text.to_string());
    }));
    let scenario = catch_unwind(AssertUnwindSafe(|| {
        let _ = Scenario::parse(text, &path.display().to_string());
    }));
    assert!(
        scenario.is_ok(),
        "Scenario::parse panicked on this input ({}):\n{text}",
        path.display()
    );
    assert!(
        graph.is_ok(),
        "compile_str panicked on this input ({}):\n{text}",
        path.display()
    );
    assert!(
        skeleton.is_ok(),
        "load_skeleton_str panicked on this input ({}):\n{text}",
        path.display()
    );
    graph.unwrap()
}

/// `cases` per property, unless `PROPTEST_CASES` asks for another number (for longer
/// fuzzing sessions: `PROPTEST_CASES=20000 cargo test --release --test loader_fuzz`).
fn config(cases: u32) -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        // Never write regression files into the source tree.
        failure_persistence: None,
        ..Config::default()
    }
}

#[test]
fn the_corpus_is_complete_and_loads() {
    // Guards the properties below against testing an empty or broken corpus.
    let files = corpus();
    let names: Vec<String> = files.iter().map(|(p, _)| p.display().to_string()).collect();
    for expected in [
        "graphs/pelvis_bob.ron",
        "graphs/examples/feet_finder.ron",
        "graphs/skeletons/mannequin.ron",
        "graphs/scenarios/walk_flat.ron",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "{expected} missing from {names:?}"
        );
    }
    for (path, text) in files {
        if path.components().any(|c| c.as_os_str() == "scenarios") {
            assert!(
                Scenario::parse(text, &path.display().to_string()).is_ok(),
                "{}",
                path.display()
            );
        } else if path.components().any(|c| c.as_os_str() == "skeletons") {
            assert!(
                strider_graph::load_skeleton_str(path, text.clone()).is_ok(),
                "{}",
                path.display()
            );
        } else {
            assert!(
                strider_compiler::compile_str(path, text).is_ok(),
                "{}",
                path.display()
            );
        }
    }
}

// ---------------------------------------------------------------------------------------
// Random text
// ---------------------------------------------------------------------------------------

/// Pieces of the graph and skeleton formats, plus things that trip up readers.
const TOKENS: &[&str] = &[
    "Graph",
    "Skeleton",
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    ":",
    ",",
    ".",
    "version",
    "1",
    "0",
    "-1",
    "2",
    "99999999999999999999",
    "1e39",
    "-1e39",
    "1.5",
    "-0.0",
    "NaN",
    "inf",
    "0x1F",
    "0b101",
    "0o17",
    "1e",
    "1.",
    ".5",
    "name",
    "\"x\"",
    "\"\"",
    "\"a.b\"",
    "\"Time\"",
    "\"pelvis\"",
    "\"foot\"",
    "\"é\u{1F600}\"",
    "\"unterminated",
    "\"esc\\\"aped\"",
    "\"\\u{41}\"",
    "variables",
    "functions",
    "nodes",
    "events",
    "forward",
    "construction",
    "imports",
    "editor",
    "conventions",
    "type",
    "default",
    "tunable",
    "min",
    "max",
    "inputs",
    "outputs",
    "locals",
    "exec",
    "Float",
    "Int",
    "Bool",
    "Vec3",
    "Quat",
    "Transform",
    "Bone",
    "Name",
    "FloatArray",
    "BoneArray",
    "TransformArray",
    "var",
    "bone",
    "name",
    "euler",
    "None",
    "true",
    "false",
    "Global",
    "Local",
    "Set",
    "Run",
    "Branch",
    "ForEach",
    "For",
    "Sequence",
    "Return",
    "condition",
    "then",
    "else",
    "items",
    "element",
    "index",
    "count",
    "body",
    "Add",
    "Multiply",
    "Divide",
    "Sin",
    "GetTransform",
    "SetTransform",
    "FindBones",
    "At",
    "Append",
    "Reset",
    "Select",
    "DrawLine",
    "DeltaTime",
    "MakeTransform",
    "BreakTransform",
    "a",
    "b",
    "value",
    "translation",
    "rotation",
    "scale",
    "parent",
    "bones",
    "contacts",
    "offset",
    "//",
    "/*",
    "*/",
    "\n",
    "\t",
    " ",
    "'",
    "\\",
    "r#\"",
    "\"#",
    "#",
    "@",
    "\u{0}",
    "\u{FEFF}",
    "é",
    "∞",
    "(((((((((((((((((((((((((((((((((((((((((",
    "]]]]]]]]]]",
    "Some(",
    "()",
];

fn token_soup() -> impl Strategy<Value = String> {
    prop::collection::vec((prop::sample::select(TOKENS), 0u8..4), 0..160).prop_map(|parts| {
        let mut s = String::new();
        for (token, sep) in parts {
            s.push_str(token);
            s.push_str(["", " ", ", ", "\n"][sep as usize]);
        }
        s
    })
}

/// A soup that starts like a real file, so the parser gets past the first token.
fn headed_soup() -> impl Strategy<Value = String> {
    (
        prop::sample::select(
            &[
                "Graph(version: 1, ",
                "Graph(version: 1, nodes: { ",
                "Graph(version: 1, events: { forward: [ ",
                "Graph(version: 1, functions: { \"F\": ( ",
                "Skeleton(version: 1, bones: [ ",
                "Skeleton(version: 1, name: \"s\", bones: [ (name: \"root\", parent: None), ",
            ][..],
        ),
        token_soup(),
    )
        .prop_map(|(head, soup)| format!("{head}{soup}"))
}

proptest! {
    #![proptest_config(config(512))]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..1024)) {
        let text = String::from_utf8_lossy(&bytes);
        load_both(Path::new("graphs/fuzz.ron"), &text);
    }

    #[test]
    fn random_ascii_never_panics(text in "[ -~\n\t]{0,400}") {
        load_both(Path::new("graphs/fuzz.ron"), &text);
    }

    #[test]
    fn token_soups_never_panic(text in token_soup()) {
        load_both(Path::new("graphs/fuzz.ron"), &text);
    }

    #[test]
    fn headed_token_soups_never_panic(text in headed_soup()) {
        load_both(Path::new("graphs/fuzz.ron"), &text);
    }
}

// ---------------------------------------------------------------------------------------
// Damaged shipped files
// ---------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(config(512))]

    #[test]
    fn truncated_files_never_panic(file in any::<prop::sample::Index>(), cut in any::<prop::sample::Index>()) {
        let (path, text) = &corpus()[file.index(corpus().len())];
        let bytes = text.as_bytes();
        let cut = cut.index(bytes.len() + 1);
        load_both(path, &String::from_utf8_lossy(&bytes[..cut]));
    }

    #[test]
    fn single_byte_mutations_never_panic(
        file in any::<prop::sample::Index>(),
        at in any::<prop::sample::Index>(),
        byte in prop_oneof![
            // Mostly bytes that matter to RON, sometimes any byte.
            prop::sample::select(&b"()[]{}:,\"'./\\*#-+0123456789eE_ \nazAZ"[..]),
            any::<u8>(),
        ],
        mode in 0u8..3,
    ) {
        let (path, text) = &corpus()[file.index(corpus().len())];
        let mut bytes = text.as_bytes().to_vec();
        let at = at.index(bytes.len());
        match mode {
            0 => bytes[at] = byte,
            1 => bytes.insert(at, byte),
            _ => {
                bytes.remove(at);
            }
        }
        load_both(path, &String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn spliced_files_never_panic(
        a in any::<prop::sample::Index>(),
        b in any::<prop::sample::Index>(),
        cut_a in any::<prop::sample::Index>(),
        cut_b in any::<prop::sample::Index>(),
    ) {
        // The head of one file glued to the tail of another (or of itself).
        let (path, ta) = &corpus()[a.index(corpus().len())];
        let (_, tb) = &corpus()[b.index(corpus().len())];
        let (ba, bb) = (ta.as_bytes(), tb.as_bytes());
        let mut bytes = ba[..cut_a.index(ba.len() + 1)].to_vec();
        bytes.extend_from_slice(&bb[cut_b.index(bb.len() + 1)..]);
        load_both(path, &String::from_utf8_lossy(&bytes));
    }
}

#[test]
fn every_truncation_of_every_shipped_file_is_handled() {
    // Systematic rather than random: every file cut at (roughly) every 13th byte, and at
    // each of the last 64 bytes, where files close their brackets.
    for (path, text) in corpus() {
        let bytes = text.as_bytes();
        let tail = bytes.len().saturating_sub(64);
        for cut in (0..=bytes.len()).filter(|&c| c % 13 == 0 || c >= tail) {
            load_both(path, &String::from_utf8_lossy(&bytes[..cut]));
        }
    }
}

#[test]
fn deep_and_long_inputs_are_handled() {
    let path = Path::new("graphs/fuzz.ron");
    for open in [
        "(",
        "[",
        "{",
        "Graph(",
        "(a: ",
        "[Branch(condition: true, then: ",
    ] {
        for depth in [100, 127, 128, 129, 1_000, 100_000] {
            load_both(path, &open.repeat(depth));
            load_both(
                path,
                &format!(
                    "Graph(version: 1, nodes: {{ \"x\": {} }})",
                    open.repeat(depth)
                ),
            );
        }
    }
    // Deeply nested exec lists that the reader accepts (under its nesting limit).
    for depth in [10, 40, 60] {
        let mut steps = String::from("Set(\"X\", 1.0)");
        for _ in 0..depth {
            steps = format!("Branch(condition: true, then: [ {steps} ])");
        }
        let text = format!(
            "Graph(version: 1, variables: {{ \"X\": (type: Float) }}, events: {{ forward: [ {steps} ] }})"
        );
        load_both(path, &text);
    }
    // A long chain of nodes, each reading the previous one.
    let mut nodes = String::from("\"n0\": Add(a: 1.0, b: 1.0), ");
    for k in 1..3_000 {
        nodes.push_str(&format!("\"n{k}\": Add(a: \"n{}\", b: 1.0), ", k - 1));
    }
    let text = format!(
        "Graph(version: 1, variables: {{ \"X\": (type: Float) }}, nodes: {{ {nodes} }}, events: {{ forward: [ Set(\"X\", \"n2999\") ] }})"
    );
    assert!(load_both(path, &text), "a long but valid chain compiles");
    // Long comments, strings and numbers.
    load_both(path, &format!("/* {} */", "/* ".repeat(10_000)));
    load_both(
        path,
        &format!("Graph(version: 1, name: \"{}\")", "x".repeat(100_000)),
    );
    load_both(path, &format!("Graph(version: {})", "9".repeat(10_000)));
    load_both(path, &format!("Graph(version: 1.{})", "9".repeat(10_000)));
}

// ---------------------------------------------------------------------------------------
// Generated graphs from the node table
// ---------------------------------------------------------------------------------------

/// Picks choices from a list of random numbers, cycling through it; shrinking the list
/// shrinks the graph.
struct Dice<'a> {
    rolls: &'a [u16],
    at: usize,
}

impl Dice<'_> {
    fn roll(&mut self, n: usize) -> usize {
        if n == 0 || self.rolls.is_empty() {
            return 0;
        }
        let r = self.rolls[self.at % self.rolls.len()] as usize;
        self.at += 1;
        r % n
    }

    fn chance(&mut self, percent: usize) -> bool {
        self.roll(100) < percent
    }

    fn pick<'t, T>(&mut self, items: &'t [T]) -> &'t T {
        &items[self.roll(items.len())]
    }
}

/// Graph variables the generator declares: name and type.
const VARIABLES: &[(&str, &str)] = &[
    ("VB", "Bool"),
    ("VI", "Int"),
    ("VF", "Float"),
    ("VV", "Vec3"),
    ("VQ", "Quat"),
    ("VT", "Transform"),
    ("VBone", "Bone"),
    ("AB", "BoolArray"),
    ("AI", "IntArray"),
    ("AF", "FloatArray"),
    ("AV", "Vec3Array"),
    ("AQ", "QuatArray"),
    ("AT", "TransformArray"),
    ("ABone", "BoneArray"),
];

const BONES: &[&str] = &["root", "pelvis", "foot_l", "hand_r", "head", "spine_01"];

fn literal(d: &mut Dice<'_>, ty: ValueType, choices: &[&str]) -> String {
    if !choices.is_empty() && d.chance(70) {
        return d.pick(choices).to_string();
    }
    let num = |d: &mut Dice<'_>| {
        *d.pick(&[
            "0.0", "1.0", "-1.0", "0.5", "90.0", "-45.0", "100.0", "1e-6", "3", "0", "1e30",
        ])
    };
    match ty {
        ValueType::Bool => d.pick(&["true", "false"]).to_string(),
        ValueType::Int => d
            .pick(&["0", "1", "2", "-1", "5", "2147483647"])
            .to_string(),
        ValueType::Float => num(d).to_string(),
        ValueType::Vec3 => format!("({}, {}, {})", num(d), num(d), num(d)),
        ValueType::Quat => {
            if d.chance(50) {
                format!("euler({}, {}, {})", num(d), num(d), num(d))
            } else {
                "(0.0, 0.0, 0.0, 1.0)".to_string()
            }
        }
        ValueType::Transform => format!(
            "(translation: ({}, {}, {}), rotation: euler(0.0, {}, 0.0))",
            num(d),
            num(d),
            num(d),
            num(d)
        ),
        ValueType::Bone => {
            if d.chance(15) {
                "None".into()
            } else {
                format!("bone(\"{}\")", d.pick(BONES))
            }
        }
        ValueType::Name => format!("name(\"{}\")", d.pick(&["foot", "", "_l", "HAND", "ik"])),
        ValueType::Array(e) => {
            let n = d.roll(4);
            let items: Vec<String> = (0..n).map(|_| literal(d, e.scalar(), &[])).collect();
            format!("[{}]", items.join(", "))
        }
    }
}

/// A node the generator declared in `nodes`: its id, its outputs and whether it must be
/// `Run`.
struct Declared {
    id: String,
    outputs: Vec<(&'static str, ValueType)>,
    mutating: bool,
    /// An `Append`: never run inside a loop (see `steps`).
    appends: bool,
}

/// A value for a pin of type `ty`: a link to a declared node with a fitting output, a
/// variable, a loop name in scope, a literal, or (rarely) something wrong.
fn pin_value(
    d: &mut Dice<'_>,
    ty: ValueType,
    choices: &[&str],
    nodes: &[Declared],
    loop_names: &[(String, ValueType)],
) -> String {
    let roll = d.roll(1000);
    if roll < 350 {
        let fitting: Vec<String> = nodes
            .iter()
            .flat_map(|n| {
                let single = n.outputs.len() == 1;
                n.outputs
                    .iter()
                    .filter(|(_, t)| t.converts_to(ty))
                    .map(|(pin, _)| {
                        if single && short_link(pin) {
                            format!("\"{}\"", n.id)
                        } else {
                            format!("\"{}.{pin}\"", n.id)
                        }
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        if !fitting.is_empty() {
            return d.pick(&fitting).clone();
        }
    }
    if roll < 550 {
        let vars: Vec<&str> = VARIABLES
            .iter()
            .filter(|(_, t)| ValueType::from_name(t).is_some_and(|t| t.converts_to(ty)))
            .map(|(n, _)| *n)
            .collect();
        if !vars.is_empty() {
            return format!("var(\"{}\")", d.pick(&vars));
        }
    }
    if roll < 650 {
        let names: Vec<&String> = loop_names
            .iter()
            .filter(|(_, t)| t.converts_to(ty))
            .map(|(n, _)| n)
            .collect();
        if !names.is_empty() {
            return format!("\"{}\"", d.pick(&names));
        }
    }
    if roll < 995 {
        return literal(d, ty, choices);
    }
    // Wrong on purpose: an unknown link, a wrong type, a malformed literal, an unknown bone.
    d.pick(&[
        "\"nowhere\"",
        "\"n0.nope\"",
        "var(\"Nope\")",
        "(1.0, 2.0)",
        "true",
        "bone(\"nobody\")",
    ])
    .to_string()
}

/// Whether a single-output link is written `"id"` rather than `"id.pin"` (both are valid;
/// the choice varies with the pin name so both forms get exercised).
fn short_link(pin: &str) -> bool {
    pin.len().is_multiple_of(2)
}

/// `Kind(pin: value, ...)` for a node kind, with some optional pins left out; returns the
/// text and the chosen overload's outputs.
fn node_call(
    d: &mut Dice<'_>,
    kind: &str,
    nodes: &[Declared],
    loop_names: &[(String, ValueType)],
    id: Option<&str>,
) -> (String, Vec<(&'static str, ValueType)>) {
    let spec = registry().get(kind).expect("a registry node");
    let overload = d.pick(&spec.overloads);
    let mut pins = Vec::new();
    if let Some(id) = id {
        pins.push(format!("id: \"{id}\""));
    }
    for p in &overload.inputs {
        if p.default.is_some() && d.chance(40) {
            continue;
        }
        let value = if p.target {
            let vars: Vec<&str> = VARIABLES
                .iter()
                .filter(|(_, t)| ValueType::from_name(t) == Some(p.ty))
                .map(|(n, _)| *n)
                .collect();
            match vars.first() {
                Some(v) => format!("var(\"{v}\")"),
                None => pin_value(d, p.ty, p.choices, nodes, loop_names),
            }
        } else {
            pin_value(d, p.ty, p.choices, nodes, loop_names)
        };
        pins.push(format!("{}: {value}", p.name));
    }
    let outputs = overload.outputs.iter().map(|p| (p.name, p.ty)).collect();
    (format!("{kind}({})", pins.join(", ")), outputs)
}

fn steps(
    d: &mut Dice<'_>,
    depth: usize,
    nodes: &[Declared],
    loop_names: &mut Vec<(String, ValueType)>,
    counter: &mut usize,
) -> String {
    let mutating: Vec<&str> = registry()
        .nodes()
        .iter()
        .filter(|n| n.effect == Effect::Mutating)
        .map(|n| n.name)
        .collect();
    let n = d.roll(5);
    let mut out = Vec::new();
    for _ in 0..n {
        *counter += 1;
        let c = *counter;
        let in_loop = !loop_names.is_empty();
        let step = match d.roll(if depth >= 3 { 5 } else { 11 }) {
            0 | 1 => {
                let (name, ty) = *d.pick(VARIABLES);
                let ty = ValueType::from_name(ty).unwrap();
                format!(
                    "Set(\"{name}\", {})",
                    pin_value(d, ty, &[], nodes, loop_names)
                )
            }
            2 | 3 => {
                // No Append inside loops: ForEach reads its array in place (docs/format.md),
                // so appending to the array it walks would never end.
                let kinds: Vec<&str> = mutating
                    .iter()
                    .copied()
                    .filter(|k| !(in_loop && *k == "Append"))
                    .collect();
                let kind = *d.pick(&kinds);
                let id = d.chance(20).then(|| format!("x{c}"));
                node_call(d, kind, nodes, loop_names, id.as_deref()).0
            }
            4 => {
                // Mostly the mutating nodes (which must be Run), sometimes a pure one.
                let any = d.chance(5);
                let runnable: Vec<&String> = nodes
                    .iter()
                    .filter(|n| (n.mutating || any) && !(in_loop && n.appends))
                    .map(|n| &n.id)
                    .collect();
                match (runnable.is_empty(), d.chance(50)) {
                    (false, _) => format!("Run(\"{}\")", d.pick(&runnable)),
                    (true, true) => "Bump()".to_string(),
                    (true, false) => {
                        format!("Bump(id: \"b{c}\"), Set(\"VI\", \"b{c}\")")
                    }
                }
            }
            5 | 6 => {
                let cond = pin_value(d, ValueType::Bool, &[], nodes, loop_names);
                let then = steps(d, depth + 1, nodes, loop_names, counter);
                let other = steps(d, depth + 1, nodes, loop_names, counter);
                format!("Branch(condition: {cond}, then: [{then}], else: [{other}])")
            }
            7 => {
                let (array, ty) = *d.pick(&VARIABLES[7..]);
                let elem = ValueType::from_name(ty).unwrap().elem().unwrap().scalar();
                let (e, i) = (format!("e{c}"), format!("i{c}"));
                loop_names.push((e.clone(), elem));
                loop_names.push((i.clone(), ValueType::Int));
                let body = steps(d, depth + 1, nodes, loop_names, counter);
                loop_names.truncate(loop_names.len() - 2);
                format!(
                    "ForEach(items: var(\"{array}\"), element: \"{e}\", index: \"{i}\", body: [{body}])"
                )
            }
            8 => {
                let k = format!("k{c}");
                let count = d.pick(&["0", "1", "3", "-2"]).to_string();
                loop_names.push((k.clone(), ValueType::Int));
                let body = steps(d, depth + 1, nodes, loop_names, counter);
                loop_names.pop();
                format!("For(count: {count}, index: \"{k}\", body: [{body}])")
            }
            9 => {
                let a = steps(d, depth + 1, nodes, loop_names, counter);
                let b = steps(d, depth + 1, nodes, loop_names, counter);
                format!("Sequence([{a}], [{b}])")
            }
            _ => "Return".to_string(),
        };
        out.push(step);
    }
    out.join(", ")
}

/// A whole graph: every variable type, a pure and an impure function, random nodes and
/// random construction and forward exec lists.
fn generated_graph(rolls: &[u16]) -> String {
    let mut d = Dice { rolls, at: 0 };
    let kinds: Vec<&str> = registry().nodes().iter().map(|n| n.name).collect();
    let mut nodes: Vec<Declared> = Vec::new();
    let mut node_text = Vec::new();
    // Loop names that node pins may read: they are only valid where a loop pulls them,
    // so this is wrong often, which the checker must report rather than choke on.
    let loop_names = if d.chance(20) {
        vec![("e1".to_string(), ValueType::Float)]
    } else {
        Vec::new()
    };
    for k in 0..d.roll(14) {
        let id = format!("n{k}");
        if d.chance(10) {
            let x = pin_value(&mut d, ValueType::Float, &[], &nodes, &loop_names);
            node_text.push(format!("\"{id}\": Pure(x: {x})"));
            nodes.push(Declared {
                id,
                outputs: vec![("y", ValueType::Float)],
                mutating: false,
                appends: false,
            });
            continue;
        }
        let kind = *d.pick(&kinds);
        let (call, outputs) = node_call(&mut d, kind, &nodes, &loop_names, None);
        node_text.push(format!("\"{id}\": {call}"));
        let mutating = registry().get(kind).unwrap().effect == Effect::Mutating;
        nodes.push(Declared {
            id,
            outputs,
            mutating,
            appends: kind == "Append",
        });
    }
    let mut loop_names = Vec::new();
    let mut counter = 0;
    let construction = steps(&mut d, 0, &nodes, &mut loop_names, &mut counter);
    let forward = steps(&mut d, 0, &nodes, &mut loop_names, &mut counter);
    // Mutating nodes declared in `nodes` must be Run somewhere.
    let runs: Vec<String> = nodes
        .iter()
        .filter(|n| n.mutating && d.chance(90))
        .map(|n| format!("Run(\"{}\")", n.id))
        .collect();
    let variables: Vec<String> = VARIABLES
        .iter()
        .map(|(n, t)| format!("\"{n}\": (type: {t})"))
        .collect();
    format!(
        r#"Graph(
    version: 1,
    name: "generated",
    variables: {{ {} }},
    functions: {{
        "Pure": (inputs: {{ "x": Float }}, outputs: {{ "y": Float }},
                 nodes: {{ "s": Sin(value: "x") }}, exec: [ Return(y: "s") ]),
        "Bump": (outputs: {{ "v": Int }}, nodes: {{ "n": Add(a: var("VI"), b: 1) }},
                 exec: [ Set("VI", "n"), Return(v: var("VI")) ]),
    }},
    nodes: {{ {} }},
    events: {{
        construction: [ {construction} ],
        forward: [ {}{forward} ],
    }},
)"#,
        variables.join(", "),
        node_text.join(",\n        "),
        runs.iter().map(|r| format!("{r}, ")).collect::<String>(),
    )
}

proptest! {
    #![proptest_config(config(1024))]

    #[test]
    fn generated_graphs_compile_or_fail_cleanly_and_run_without_panicking(
        rolls in prop::collection::vec(any::<u16>(), 1..200),
    ) {
        let text = generated_graph(&rolls);
        let path = Path::new("tests/graphs/generated.ron");
        let program = catch_unwind(AssertUnwindSafe(|| strider_compiler::compile_str(path, &text)));
        let program = match program {
            Ok(p) => p,
            Err(_) => panic!("compile_str panicked on:\n{text}"),
        };
        if let Ok(program) = program {
            let ran = catch_unwind(AssertUnwindSafe(|| {
                if let Ok(mut inst) = Instance::new(Arc::new(program), mannequin()) {
                    for (k, dt) in [1.0 / 60.0, 0.0, f32::NAN, 0.25].into_iter().enumerate() {
                        inst.run_forward(&FrameInput { dt, ..Default::default() }, &EmptyWorld, k % 2 == 0);
                    }
                }
            }));
            prop_assert!(ran.is_ok(), "running the compiled graph panicked:\n{}", text);
        }
    }
}

#[test]
fn the_generator_reaches_the_code_generator() {
    // The property above is only meaningful if a fair share of generated graphs compile
    // (reaching codegen and the VM) and a fair share do not (reaching error reporting).
    let mut compiled = 0;
    let total = 200;
    for seed in 0..total {
        let rolls: Vec<u16> = (0..120u32)
            .map(|k| ((seed * 7919 + k * 104_729 + k * k * 31) % 65_521) as u16)
            .collect();
        let text = generated_graph(&rolls);
        if strider_compiler::compile_str(Path::new("tests/graphs/generated.ron"), &text).is_ok() {
            compiled += 1;
        }
    }
    assert!(
        compiled >= total / 4 && compiled <= total * 19 / 20,
        "{compiled} of {total} generated graphs compiled"
    );
}
