//! Diagnostics, snapshot-style: one small malformed file per error class under
//! `tests/malformed/`, and for each the exact list of problems reported — line and column
//! (counted by hand from the file), message, node, pin, and the key advice of the hint.
//!
//! Each class test compares the diagnostics sorted by location, so that it checks *what* is
//! reported; the order in which problems are reported is checked once, by
//! `several_errors_are_reported_in_source_order`.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use strider_graph::Diagnostic;
use strider_vm::{Instance, InstantiateError, MissingBone};

/// One expected diagnostic.
#[derive(Clone, Debug)]
struct Expect {
    /// The file it is reported in, when not the file compiled.
    path: Option<&'static str>,
    line: usize,
    col: usize,
    message: &'static str,
    /// `message` is only a prefix (the rest is OS error text).
    prefix: bool,
    node: Option<&'static str>,
    pin: Option<&'static str>,
    /// Text the hint must contain; `None`: there must be no hint.
    hint: Option<&'static str>,
}

fn at(line: usize, col: usize, message: &'static str) -> Expect {
    Expect {
        path: None,
        line,
        col,
        message,
        prefix: false,
        node: None,
        pin: None,
        hint: None,
    }
}

impl Expect {
    fn node(mut self, node: &'static str) -> Self {
        self.node = Some(node);
        self
    }

    fn pin(mut self, pin: &'static str) -> Self {
        self.pin = Some(pin);
        self
    }

    fn hint(mut self, contains: &'static str) -> Self {
        self.hint = Some(contains);
        self
    }

    fn prefix(mut self) -> Self {
        self.prefix = true;
        self
    }

    fn in_file(mut self, path: &'static str) -> Self {
        self.path = Some(path);
        self
    }
}

fn show(diags: &[Diagnostic]) -> String {
    diags
        .iter()
        .map(|d| format!("{d}\n    (node {:?}, pin {:?})", d.node, d.pin))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Compiles `path`, which must fail, and returns what was reported.
fn compile_errors(path: &str) -> Vec<Diagnostic> {
    match strider_compiler::compile_file(Path::new(path)) {
        Ok(_) => panic!("{path} compiled, but it is malformed"),
        Err(d) => {
            assert!(!d.is_empty(), "{path}: an error without diagnostics");
            d
        }
    }
}

/// Loads the skeleton file `path`, which must fail, and returns what was reported.
fn skeleton_errors(path: &str) -> Vec<Diagnostic> {
    match strider_graph::load_skeleton(Path::new(path)) {
        Ok(s) => panic!("{path} loaded as {s:?}, but it is malformed"),
        Err(d) => d,
    }
}

/// Asserts that `actual` (sorted by file and location) is exactly `expected`.
fn assert_diags(file: &str, actual: &[Diagnostic], expected: &[Expect]) {
    let mut actual = actual.to_vec();
    actual.sort_by(|a, b| (&a.path, a.line, a.col).cmp(&(&b.path, b.line, b.col)));
    let all = show(&actual);
    assert_eq!(
        actual.len(),
        expected.len(),
        "{file}: expected {} diagnostics, got:\n{all}",
        expected.len()
    );
    for (i, (d, e)) in actual.iter().zip(expected).enumerate() {
        let ctx = format!("{file}: diagnostic #{i}:\n{d}\n\nall diagnostics:\n{all}");
        assert_eq!(d.path, PathBuf::from(e.path.unwrap_or(file)), "path; {ctx}");
        assert_eq!((d.line, d.col), (e.line, e.col), "line:col; {ctx}");
        if e.prefix {
            assert!(
                d.message.starts_with(e.message),
                "message should start with {:?}; {ctx}",
                e.message
            );
        } else {
            assert_eq!(d.message, e.message, "message; {ctx}");
        }
        assert_eq!(d.node.as_deref(), e.node, "node; {ctx}");
        assert_eq!(d.pin.as_deref(), e.pin, "pin; {ctx}");
        match (e.hint, &d.hint) {
            (Some(want), Some(hint)) => {
                assert!(hint.contains(want), "hint should contain {want:?}; {ctx}")
            }
            (Some(want), None) => panic!("expected a hint containing {want:?}; {ctx}"),
            (None, Some(_)) => panic!("expected no hint; {ctx}"),
            (None, None) => {}
        }
    }
}

fn check_graph(file: &str, expected: &[Expect]) {
    assert_diags(file, &compile_errors(file), expected);
}

// ---- RON syntax ----

// A syntax error ends the reading of the file, so each file holds one. These diagnostics
// carry no hint: the advice is in the message.

#[test]
fn ron_syntax_missing_comma() {
    check_graph(
        "tests/malformed/ron_syntax_missing_comma.ron",
        &[at(
            5,
            5,
            "RON syntax: expected `,` or `)` after the field value, found `nodes`",
        )],
    );
}

#[test]
fn ron_syntax_unclosed_paren() {
    check_graph(
        "tests/malformed/ron_syntax_unclosed_paren.ron",
        &[at(
            7,
            5,
            "RON syntax: expected `,` or `)` after the field value, found `}` \
             (`(` opened at 6:19 is still open)",
        )],
    );
}

#[test]
fn ron_syntax_unexpected_end_of_file() {
    check_graph(
        "tests/malformed/ron_syntax_eof.ron",
        &[at(
            6,
            1,
            "RON syntax: unexpected end of file: `(` opened at 2:6 is never closed",
        )],
    );
}

// ---- Names: node types, pins, links, ids, variables ----

#[test]
fn unknown_node_type() {
    check_graph(
        "tests/malformed/unknown_node_type.ron",
        &[
            at(10, 16, "unknown node type `Lepr`")
                .node("mid")
                .hint("did you mean `Lerp`?"),
            // An anonymous exec node is named by its type.
            at(15, 13, "unknown node type `DrawTransfrom`")
                .node("DrawTransfrom")
                .hint("did you mean `DrawTransform`?"),
        ],
    );
}

#[test]
fn unknown_pin() {
    check_graph(
        "tests/malformed/unknown_pin.ron",
        &[
            at(11, 21, "unknown pin `valeu` on Sin")
                .node("wave")
                .pin("valeu")
                .hint("did you mean `value`?"),
            at(12, 36, "unknown pin `result` on MakeVector")
                .node("side")
                .pin("result")
                .hint(
                    "`result` is an output of MakeVector; link to it from another node as \
                     \"side.result\"",
                ),
        ],
    );
}

#[test]
fn pin_given_twice() {
    check_graph(
        "tests/malformed/pin_given_twice.ron",
        &[at(10, 36, "pin `a` is given twice").node("sum")],
    );
}

#[test]
fn missing_required_input() {
    check_graph(
        "tests/malformed/missing_required_input.ron",
        &[
            at(9, 18, "missing required input `value` of BreakTransform")
                .node("parts")
                .pin("value")
                .hint("add `value: ...` (Transform: "),
        ],
    );
}

#[test]
fn type_mismatch_float_into_vec3() {
    check_graph(
        "tests/malformed/type_mismatch.ron",
        &[
            at(
                12,
                46,
                "type mismatch on pin `translation` of MakeTransform: expected Vec3, found Float",
            )
            .node("target")
            .pin("translation")
            .hint(
                "insert a MakeVector node (e.g. MakeVector(z: ...)) to build a Vec3 from a Float",
            ),
            // An overloaded node: no single pin is wrong, so the node is named.
            at(
                13,
                19,
                "type mismatch: Add does not take (a: Float, b: Vec3)",
            )
            .node("moved")
            .hint(
                "to combine a Float with a Vec3, use Scale(value: vector, factor: float) or build \
                 a vector with MakeVector; Add takes (a: Float, b: Float) or (a: Int, b: Int) \
                 or (a: Vec3, b: Vec3)",
            ),
        ],
    );
}

#[test]
fn link_to_unknown_node() {
    check_graph(
        "tests/malformed/link_unknown_node.ron",
        &[
            at(11, 22, "link to unknown node `Time`")
                .node("t")
                .pin("a")
                .hint("`Time` is a variable: write var(\"Time\")"),
            at(11, 33, "link to unknown node `dtt`")
                .node("t")
                .pin("b")
                .hint("did you mean `dt`?"),
        ],
    );
}

#[test]
fn link_to_unknown_pin_of_existing_node() {
    check_graph(
        "tests/malformed/link_unknown_pin.ron",
        &[
            at(
                15,
                24,
                "link to unknown pin `nope` of node `parts` (BreakTransform)",
            )
            .node("parts")
            .pin("nope")
            .hint("its outputs are: translation, rotation, scale"),
            at(
                16,
                24,
                "link to unknown pin `rotaton` of node `parts` (BreakTransform)",
            )
            .node("parts")
            .pin("rotaton")
            .hint("did you mean `parts.rotation`?"),
        ],
    );
}

#[test]
fn duplicate_id() {
    check_graph(
        "tests/malformed/duplicate_id.ron",
        &[
            // Inline exec node `id:` equal to a `nodes` key.
            at(
                15,
                31,
                "duplicate id `pose`: another node, input or loop name in this scope already uses \
                 it",
            )
            .node("pose")
            .hint("ids must be unique within a graph's top level and within each function"),
            // Loop element name equal to a node id.
            at(
                16,
                50,
                "duplicate id `dt`: another node, input or loop name in this scope already uses it",
            )
            .node("dt")
            .hint("ids must be unique within a graph's top level and within each function"),
        ],
    );
}

#[test]
fn unknown_variable_in_var_and_in_set() {
    check_graph(
        "tests/malformed/unknown_variable.ron",
        &[
            at(11, 22, "unknown variable `Tiem`")
                .node("t")
                .pin("a")
                .hint("did you mean `Time`?"),
            at(14, 24, "unknown variable `Tmie`").hint("did you mean `Time`?"),
        ],
    );
}

#[test]
fn write_to_non_variable() {
    check_graph(
        "tests/malformed/write_to_non_variable.ron",
        &[
            at(
                12,
                26,
                "write to a non-variable: SetAt changes its `array` input in place, so it must \
                 be a variable",
            )
            .node("SetAt")
            .pin("array")
            // The key advice; the array type it names is checked by
            // `set_at_hint_names_the_array_type`.
            .hint("write `array: var(\"Name\")` with a "),
            at(13, 17, "write to a non-variable: `dt` is a node")
                .hint("Set writes variables declared in `variables` (or a function's `locals`)"),
        ],
    );
}

#[test]
fn set_at_hint_names_the_array_type() {
    let diags = compile_errors("tests/malformed/write_to_non_variable.ron");
    let hint = diags
        .iter()
        .find(|d| d.pin.as_deref() == Some("array"))
        .and_then(|d| d.hint.clone())
        .unwrap_or_default();
    assert_eq!(
        hint,
        "write `array: var(\"Name\")` with a BoneArray variable",
        "{}",
        show(&diags)
    );
}

// ---- Structure: cycles, exec lists ----

#[test]
fn data_flow_cycle_names_every_node_along_the_links() {
    check_graph(
        "tests/malformed/data_flow_cycle.ron",
        &[
            at(10, 14, "data-flow cycle: a → b → c → a")
                .node("a")
                .hint("a node cannot depend on its own output"),
            // Declared against the flow: the path still follows the links.
            at(13, 14, "data-flow cycle: x → z → y → x")
                .node("x")
                .hint("keep state across frames in a variable"),
        ],
    );
}

#[test]
fn exec_chain_problems() {
    check_graph(
        "tests/malformed/exec_chain.ron",
        &[
            at(
                8,
                17,
                "node `draw` (DrawTransform) changes state but is not reachable from any event",
            )
            .node("draw")
            .hint("add `Run(\"draw\")` to an exec list, or write the node inline in one"),
            at(
                12,
                17,
                "pure node used as exec: `rest` (GetTransform) only computes a value",
            )
            .node("rest")
            .hint("remove the Run"),
            at(
                13,
                13,
                "pure node used as exec: Sin only computes a value, and has no effect in an exec \
                 list",
            )
            .node("Sin")
            .hint("declare it in `nodes` with an id and link its output where it is needed"),
        ],
    );
}

// ---- Functions ----

#[test]
fn unknown_function() {
    check_graph(
        "tests/malformed/unknown_function.ron",
        &[
            at(18, 14, "unknown node type `Wobbel`")
                .node("w")
                .hint("did you mean `Wobble`?"),
            at(19, 14, "unknown node type `Frobnicate`")
                .node("f")
                .hint("see `strider nodes` for the node types"),
        ],
    );
}

#[test]
fn recursion() {
    check_graph(
        "tests/malformed/recursion.ron",
        &[at(9, 9, "recursion: Ping → Pong → Ping").hint(
            "a function may not call itself, directly or through others — use a For or ForEach \
             loop",
        )],
    );
}

#[test]
fn wrong_function_arity() {
    check_graph(
        "tests/malformed/function_arity.ron",
        &[
            at(
                18,
                18,
                "wrong arguments: call of `Mad` is missing input `k`",
            )
            .node("short")
            .pin("k")
            .hint("`Mad` takes (x: Float, k: Float)"),
            at(
                19,
                38,
                "wrong arguments: function `Mad` has no input `scale`",
            )
            .node("long")
            .pin("scale")
            .hint("`Mad` takes 2 input(s): x, k"),
        ],
    );
}

// ---- Imports ----

#[test]
fn import_not_found() {
    check_graph(
        "tests/malformed/import_not_found.ron",
        &[
            // The rest of the message is the OS error text.
            at(
                5,
                15,
                "import not found: `tests/malformed/lib/missing.ron` (",
            )
            .prefix()
            .hint("import paths are relative to the folder of the file that imports them"),
        ],
    );
}

#[test]
fn import_cycle() {
    check_graph(
        "tests/malformed/import_cycle.ron",
        &[
            // Reported at the import that closes the cycle, in the library that writes it.
            at(
                5,
                15,
                "import cycle: cycle_a.ron → cycle_b.ron → cycle_a.ron",
            )
            .in_file("tests/malformed/lib/cycle_b.ron")
            .hint("a library must not import, directly or indirectly, a file that imports it"),
        ],
    );
}

// ---- Bones: checked when an instance is created ----

fn mannequin() -> strider_graph::SkeletonFile {
    strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .unwrap_or_else(|d| panic!("{}", show(&d)))
}

fn unknown_bone_error() -> InstantiateError {
    let file = "tests/malformed/unknown_bone.ron";
    let program = strider_compiler::compile_file(Path::new(file)).unwrap_or_else(|d| {
        panic!(
            "{file} should compile (bones are checked later):\n{}",
            show(&d)
        )
    });
    match Instance::new(Arc::new(program), mannequin().skeleton) {
        Ok(_) => panic!("{file}: an instance was created with unknown bones"),
        Err(e) => e,
    }
}

/// `(line, col)` of a `path:line:col` location.
fn line_col(location: &str) -> (usize, usize) {
    let mut parts = location
        .rsplit(':')
        .map(|n| n.parse::<usize>().unwrap_or(0));
    let col = parts.next().unwrap_or(0);
    (parts.next().unwrap_or(0), col)
}

#[test]
fn unknown_bone_name_fails_instantiation() {
    let InstantiateError::MissingBones { skeleton, missing } = unknown_bone_error();
    // The instance does not know the skeleton's name; a host that does fills it in.
    assert_eq!(skeleton, "");
    let mut sorted = missing.clone();
    sorted.sort_by_key(|m| line_col(&m.location));
    assert_eq!(missing, sorted, "missing bones in source order");
    assert_eq!(
        sorted,
        vec![
            MissingBone {
                name: "pelvsi".into(),
                location: "tests/malformed/unknown_bone.ron:7:36".into(),
                suggestion: Some("pelvis".into()),
            },
            MissingBone {
                name: "tail_03".into(),
                location: "tests/malformed/unknown_bone.ron:11:32".into(),
                suggestion: None,
            },
        ]
    );

    let printed = |skeleton: &str| {
        InstantiateError::MissingBones {
            skeleton: skeleton.into(),
            missing: sorted.clone(),
        }
        .to_string()
    };
    assert_eq!(
        printed(""),
        "tests/malformed/unknown_bone.ron:7:36: error: unknown bone `pelvsi`\n  \
         hint: did you mean `pelvis`?\n\
         tests/malformed/unknown_bone.ron:11:32: error: unknown bone `tail_03`"
    );
    assert_eq!(
        printed("mannequin"),
        "tests/malformed/unknown_bone.ron:7:36: error: unknown bone `pelvsi` in \
         skeleton `mannequin`\n  hint: did you mean `pelvis`?\n\
         tests/malformed/unknown_bone.ron:11:32: error: unknown bone `tail_03` in \
         skeleton `mannequin`"
    );
}

// ---- Skeleton files ----

#[test]
fn skeleton_file_errors_are_all_reported() {
    let file = "tests/malformed/skeleton_errors.ron";
    // Skeleton errors point at the bone's `(` and put any suggestion in the message; they
    // carry no hint.
    assert_diags(
        file,
        &skeleton_errors(file),
        &[
            at(
                9,
                9,
                "bone name `pelvis` is used twice; bone names must be unique",
            ),
            at(
                10,
                9,
                "rest rotation is not a unit quaternion (length 2); normalise it or write it as \
                 euler(x, y, z)",
            ),
            at(
                11,
                9,
                "unknown parent bone `pelivs`; did you mean `pelvis`?",
            ),
            at(12, 9, "the parent chain loops: loop_a → loop_b → loop_a"),
        ],
    );
}

// ---- Several errors in one file ----

fn many_errors_expected() -> Vec<Expect> {
    vec![
        at(12, 26, "unknown variable `Tiem`")
            .node("t")
            .pin("a")
            .hint("did you mean `Time`?"),
        at(13, 23, "unknown pin `valeu` on Sin")
            .node("wave")
            .pin("valeu")
            .hint("did you mean `value`?"),
        at(
            14,
            46,
            "type mismatch on pin `translation` of MakeTransform: expected Vec3, found Float",
        )
        .node("target")
        .pin("translation")
        .hint("MakeVector"),
        at(
            15,
            19,
            "node `draw` (DrawTransform) changes state but is not reachable from any event",
        )
        .node("draw")
        .hint("add `Run(\"draw\")`"),
        at(19, 17, "unknown variable `Tmie`").hint("did you mean `Time`?"),
        at(
            20,
            17,
            "pure node used as exec: `dt` (DeltaTime) only computes a value",
        )
        .node("dt")
        .hint("remove the Run"),
        at(21, 55, "link to unknown node `targte`")
            .node("SetTransform")
            .pin("value")
            .hint("did you mean `target`?"),
    ]
}

#[test]
fn several_errors_are_all_reported() {
    let file = "tests/malformed/many_errors.ron";
    assert_diags(file, &compile_errors(file), &many_errors_expected());
}

#[test]
fn several_errors_are_reported_in_source_order() {
    let file = "tests/malformed/many_errors.ron";
    let diags = compile_errors(file);
    let got: Vec<(usize, usize)> = diags.iter().map(|d| (d.line, d.col)).collect();
    let want: Vec<(usize, usize)> = many_errors_expected()
        .iter()
        .map(|e| (e.line, e.col))
        .collect();
    assert_eq!(got, want, "{}", show(&diags));
}

// ---- The printed form ----

#[test]
fn diagnostic_display_is_path_line_col_error_message() {
    let d = |node: Option<&str>, pin: Option<&str>, hint: Option<&str>| Diagnostic {
        path: PathBuf::from("graphs/bob.ron"),
        line: 12,
        col: 46,
        message: "type mismatch".into(),
        node: node.map(Into::into),
        pin: pin.map(Into::into),
        hint: hint.map(Into::into),
    };
    assert_eq!(
        d(
            Some("lifted"),
            Some("translation"),
            Some("insert a MakeVector node")
        )
        .to_string(),
        "graphs/bob.ron:12:46: error: type mismatch [node `lifted`, pin `translation`]\n  hint: \
         insert a MakeVector node"
    );
    assert_eq!(
        d(Some("lifted"), None, None).to_string(),
        "graphs/bob.ron:12:46: error: type mismatch [node `lifted`]"
    );
    assert_eq!(
        d(None, Some("bone"), None).to_string(),
        "graphs/bob.ron:12:46: error: type mismatch [pin `bone`]"
    );
    assert_eq!(
        d(None, None, Some("fix it")).to_string(),
        "graphs/bob.ron:12:46: error: type mismatch\n  hint: fix it"
    );

    // As printed for a real file.
    let shown: Vec<String> = compile_errors("tests/malformed/unknown_pin.ron")
        .iter()
        .map(ToString::to_string)
        .collect();
    assert!(
        shown.contains(
            &"tests/malformed/unknown_pin.ron:11:21: error: unknown pin `valeu` on Sin [node \
              `wave`, pin `valeu`]\n  hint: did you mean `value`?"
                .to_string()
        ),
        "{shown:#?}"
    );
    let shown: Vec<String> = compile_errors("tests/malformed/link_unknown_node.ron")
        .iter()
        .map(ToString::to_string)
        .collect();
    assert!(
        shown.contains(
            &"tests/malformed/link_unknown_node.ron:11:33: error: link to unknown node `dtt` \
              [node `t`, pin `b`]\n  hint: did you mean `dt`?"
                .to_string()
        ),
        "{shown:#?}"
    );
}
