//! The node table: one entry per built-in node, from which the compiler's type checking,
//! the executor's operand layout, `strider nodes` and `docs/nodes.md` are all derived.

use crate::ops::{Access, Op, Operand};
use crate::types::{Elem, Value, ValueType};
use glam::{Quat, Vec3};
use rustc_hash::FxHashMap;
use std::fmt::Write as _;
use std::sync::OnceLock;
use strider_core::Transform;

/// Whether a node only computes outputs from inputs, or changes state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Effect {
    /// Pulled by data links, evaluated once per exec step that needs it.
    Pure,
    /// Changes the pose, a variable or the debug output; must sit in an exec list.
    Mutating,
}

/// One input or output pin.
#[derive(Clone, Debug, PartialEq)]
pub struct PinSpec {
    /// The name written in graph files.
    pub name: &'static str,
    /// The pin's type.
    pub ty: ValueType,
    /// Value used when an input is not given; `None` makes the input required.
    pub default: Option<Value>,
    /// One line: meaning, units and space.
    pub doc: &'static str,
    /// For an `Int` input that selects a mode: the names a file may write instead of the
    /// number (index = value), e.g. `Global` / `Local`.
    pub choices: &'static [&'static str],
    /// The input must be a variable (`var("Name")`), which the node writes in place.
    pub target: bool,
}

/// One typed signature of a node and the op it compiles to. Operands of the op are the
/// input slots in this order, then the output slots, then the state slots.
#[derive(Clone, Debug, PartialEq)]
pub struct Overload {
    /// The instruction this signature compiles to.
    pub op: Op,
    /// Input pins, in operand order.
    pub inputs: Vec<PinSpec>,
    /// Output pins, in operand order after the inputs.
    pub outputs: Vec<PinSpec>,
    /// Hidden per-instance state of a stateful node (e.g. a spring's velocity), in operand
    /// order after the outputs. Allocated once per node and call site, kept across frames,
    /// zero at instantiation.
    pub state: Vec<ValueType>,
}

impl Overload {
    /// The op's operands: each input read (a `target` array read and edited in place),
    /// each output written, each state slot read and written.
    #[must_use]
    pub fn operands(&self) -> Vec<Operand> {
        let input = |p: &PinSpec| {
            let access = if p.target {
                Access::ReadWrite
            } else {
                Access::Read
            };
            Operand::Slot(p.ty, access)
        };
        let inputs = self.inputs.iter().map(input);
        let outputs = self
            .outputs
            .iter()
            .map(|p| Operand::Slot(p.ty, Access::Write));
        let state = self
            .state
            .iter()
            .map(|&t| Operand::Slot(t, Access::ReadWrite));
        inputs.chain(outputs).chain(state).collect()
    }
}

/// A built-in node: name, docs, effect and its overloads.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeSpec {
    /// The type name written in graph files (`VectorLerp`).
    pub name: &'static str,
    /// Section of the node reference.
    pub category: &'static str,
    /// Whether it is pulled by data or placed in an exec list.
    pub effect: Effect,
    /// What the node does, with its formula and its behaviour on degenerate input.
    pub doc: &'static str,
    /// A line of RON using the node.
    pub example: &'static str,
    /// Typed signatures; the compiler picks the first that fits the inputs.
    pub overloads: Vec<Overload>,
}

/// All built-in nodes, by name.
#[derive(Debug)]
pub struct Registry {
    nodes: Vec<NodeSpec>,
    index: FxHashMap<&'static str, usize>,
    /// Each node op's operands (inputs, outputs, state) and each fused op's (see
    /// [`Op::operands`]).
    layouts: FxHashMap<Op, Vec<Operand>>,
}

/// The built-in node table, built once.
pub fn registry() -> &'static Registry {
    static REGISTRY: OnceLock<Registry> = OnceLock::new();
    REGISTRY.get_or_init(|| {
        let nodes = build();
        let index = nodes.iter().enumerate().map(|(i, n)| (n.name, i)).collect();
        let mut layouts = FxHashMap::default();
        for o in nodes.iter().flat_map(|n| &n.overloads) {
            layouts.entry(o.op).or_insert_with(|| o.operands());
        }
        // A fused op's operands are its two parts' laid end to end.
        for (fused, (first, second)) in Op::FUSED {
            if let (Some(a), Some(b)) = (layouts.get(&first), layouts.get(&second)) {
                let both = [a.as_slice(), b.as_slice()].concat();
                layouts.insert(fused, both);
            }
        }
        Registry {
            nodes,
            index,
            layouts,
        }
    })
}

impl Registry {
    /// The node called `name`.
    #[must_use]
    pub fn get(&self, name: &str) -> Option<&NodeSpec> {
        self.index.get(name).map(|&i| &self.nodes[i])
    }

    /// The operands of node op or fused op `op`, if a node compiles to it (a fused op: if
    /// nodes compile to both its parts).
    #[must_use]
    pub(crate) fn layout(&self, op: Op) -> Option<&[Operand]> {
        self.layouts.get(&op).map(Vec::as_slice)
    }

    /// Every node, in reference order.
    #[must_use]
    pub fn nodes(&self) -> &[NodeSpec] {
        &self.nodes
    }

    /// The node name closest to `name`, for "did you mean" hints.
    #[must_use]
    pub fn suggest(&self, name: &str) -> Option<&'static str> {
        strider_core::skeleton::closest(name, self.nodes.iter().map(|n| n.name))
            .and_then(|s| self.get(&s).map(|n| n.name))
    }

    /// The node reference as Markdown (`docs/nodes.md`).
    #[must_use]
    pub fn markdown(&self) -> String {
        let mut out = String::new();
        out.push_str("# Node reference\n\n");
        out.push_str(
            "Generated by `strider nodes --markdown` from the node table in \
             `crates/strider-nodes/src/table.rs`; a test keeps this file equal to it.\n\n\
             Conventions: rig space is +Z up, +Y forward, +X the character's left; lengths \
             in centimetres, angles in degrees, time in seconds. *Pure* nodes are pulled by \
             data links; *mutating* nodes sit in an exec list. Inputs without a default are \
             required. `Int → Float` is the only implicit conversion.\n\n\
             Exec statements (`Set`, `Run`, `Branch`, `ForEach`, `For`, `Sequence`, \
             `Return`) and function calls are described in [format.md](format.md).\n",
        );
        let mut category = "";
        for node in &self.nodes {
            if node.category != category {
                category = node.category;
                let _ = write!(out, "\n## {category}\n");
            }
            let effect = match node.effect {
                Effect::Pure => "pure",
                Effect::Mutating => "mutating",
            };
            let _ = write!(out, "\n### {}\n\n*{effect}.* {}\n\n", node.name, node.doc);
            let _ = writeln!(out, "```ron\n{}\n```\n", node.example);
            for (i, o) in node.overloads.iter().enumerate() {
                if node.overloads.len() > 1 {
                    let sig: Vec<&str> = o.inputs.iter().map(|p| p.ty.name()).collect();
                    let _ = writeln!(out, "Overload {} ({}):\n", i + 1, sig.join(", "));
                }
                out.push_str("| pin | dir | type | default | meaning |\n|---|---|---|---|---|\n");
                for p in &o.inputs {
                    let default = match &p.default {
                        None => "required".to_string(),
                        Some(v) if !p.choices.is_empty() => match v {
                            Value::Int(i) => p.choices.get(*i as usize).unwrap_or(&"?").to_string(),
                            other => other.to_string(),
                        },
                        Some(v) => format!("`{v}`"),
                    };
                    let mut doc = p.doc.to_string();
                    if !p.choices.is_empty() {
                        let _ = write!(doc, " One of: {}.", p.choices.join(", "));
                    }
                    if p.target {
                        doc.push_str(" Must be a variable (`var(\"Name\")`); written in place.");
                    }
                    let _ = writeln!(out, "| `{}` | in | {} | {default} | {doc} |", p.name, p.ty);
                }
                for p in &o.outputs {
                    let _ = writeln!(out, "| `{}` | out | {} | | {} |", p.name, p.ty, p.doc);
                }
                out.push('\n');
            }
        }
        out
    }
}

// ---- table construction helpers ----

fn input(name: &'static str, ty: ValueType, doc: &'static str) -> PinSpec {
    PinSpec {
        name,
        ty,
        default: None,
        doc,
        choices: &[],
        target: false,
    }
}

fn opt(name: &'static str, default: Value, doc: &'static str) -> PinSpec {
    PinSpec {
        ty: default.ty(),
        default: Some(default),
        ..input(name, ValueType::Bool, doc)
    }
}

fn choice(
    name: &'static str,
    choices: &'static [&'static str],
    default: i32,
    doc: &'static str,
) -> PinSpec {
    PinSpec {
        choices,
        ..opt(name, Value::Int(default), doc)
    }
}

fn target(name: &'static str, ty: ValueType, doc: &'static str) -> PinSpec {
    PinSpec {
        target: true,
        ..input(name, ty, doc)
    }
}

fn output(name: &'static str, ty: ValueType, doc: &'static str) -> PinSpec {
    input(name, ty, doc)
}

fn zero_of(ty: ValueType) -> Value {
    ty.zero()
}

struct Builder {
    nodes: Vec<NodeSpec>,
    category: &'static str,
}

impl Builder {
    fn node(
        &mut self,
        name: &'static str,
        effect: Effect,
        doc: &'static str,
        example: &'static str,
        overloads: Vec<Overload>,
    ) {
        self.nodes.push(NodeSpec {
            name,
            category: self.category,
            effect,
            doc,
            example,
            overloads,
        });
    }

    fn pure(
        &mut self,
        name: &'static str,
        doc: &'static str,
        example: &'static str,
        overloads: Vec<Overload>,
    ) {
        self.node(name, Effect::Pure, doc, example, overloads);
    }
}

fn ov(op: Op, inputs: Vec<PinSpec>, outputs: Vec<PinSpec>) -> Overload {
    Overload {
        op,
        inputs,
        outputs,
        state: Vec::new(),
    }
}

/// A two-input node over several types: `(a, b) -> result`, inputs defaulting to zero.
fn binary(ops: &[(ValueType, Op)], out: Option<ValueType>, doc_a: &'static str) -> Vec<Overload> {
    ops.iter()
        .map(|&(ty, op)| {
            ov(
                op,
                vec![
                    opt("a", zero_of(ty), doc_a),
                    opt("b", zero_of(ty), "Second operand."),
                ],
                vec![output("result", out.unwrap_or(ty), "The result.")],
            )
        })
        .collect()
}

/// A one-input node over several types: `value -> result`.
fn unary(ops: &[(ValueType, Op)], out: Option<ValueType>) -> Vec<Overload> {
    ops.iter()
        .map(|&(ty, op)| {
            ov(
                op,
                vec![opt("value", zero_of(ty), "The operand.")],
                vec![output("result", out.unwrap_or(ty), "The result.")],
            )
        })
        .collect()
}

const F: ValueType = ValueType::Float;
const I: ValueType = ValueType::Int;
const B: ValueType = ValueType::Bool;
const V: ValueType = ValueType::Vec3;
const Q: ValueType = ValueType::Quat;
const T: ValueType = ValueType::Transform;
const BONE: ValueType = ValueType::Bone;

/// Spaces a bone transform can be read or written in.
pub const SPACES: &[&str] = &["Global", "Local"];
/// Euler orders, as in [`strider_core::EulerOrder`].
pub const EULER_ORDERS: &[&str] = &["XYZ", "ZYX"];

fn build() -> Vec<NodeSpec> {
    let mut b = Builder {
        nodes: Vec::new(),
        category: "Math",
    };
    let f0 = || Value::Float(0.0);

    b.pure(
        "Add",
        "`a + b`. Ints wrap on overflow.",
        r#""sum": Add(a: "x", b: 1.0),"#,
        binary(
            &[(F, Op::AddF), (I, Op::AddI), (V, Op::AddV)],
            None,
            "First operand.",
        ),
    );
    b.pure(
        "Subtract",
        "`a − b`.",
        r#""d": Subtract(a: "target", b: "start"),"#,
        binary(
            &[(F, Op::SubF), (I, Op::SubI), (V, Op::SubV)],
            None,
            "First operand.",
        ),
    );
    b.pure(
        "Multiply",
        "`a · b`: product of numbers, component-wise for vectors, composition for \
         rotations and transforms (`a · b` applies `b` first, then `a`: parent · child).",
        r#""rot": Multiply(a: "platform_rotation", b: "foot_rotation"),"#,
        {
            let mut o = binary(
                &[(F, Op::MulF), (I, Op::MulI), (V, Op::MulV)],
                None,
                "First operand.",
            );
            o.push(ov(
                Op::MulQ,
                vec![
                    opt(
                        "a",
                        Value::Quat(Quat::IDENTITY),
                        "Parent rotation, applied second.",
                    ),
                    opt(
                        "b",
                        Value::Quat(Quat::IDENTITY),
                        "Child rotation, applied first.",
                    ),
                ],
                vec![output("result", Q, "`a · b`, normalised.")],
            ));
            o.push(ov(
                Op::MulT,
                vec![
                    opt(
                        "a",
                        Value::Transform(Transform::IDENTITY),
                        "Parent transform.",
                    ),
                    opt(
                        "b",
                        Value::Transform(Transform::IDENTITY),
                        "Child transform.",
                    ),
                ],
                vec![output("result", T, "`a · b`: `b` placed in `a`'s space.")],
            ));
            o
        },
    );
    b.pure(
        "Divide",
        "`a / b`; component-wise for vectors. Dividing by zero gives 0 (per component), \
         never NaN or infinity.",
        r#""ground_time": Divide(a: var("MaxFootStrideLength"), b: "speed"),"#,
        binary(
            &[(F, Op::DivF), (I, Op::DivI), (V, Op::DivV)],
            None,
            "Dividend.",
        ),
    );
    b.pure(
        "Modulo",
        "Floored remainder `a − b·floor(a / b)` (the result has the sign of `b`); 0 when \
         `b` is 0.",
        r#""wrapped": Modulo(a: "angle", b: 360.0),"#,
        binary(&[(F, Op::FmodF), (I, Op::ModI)], None, "Dividend."),
    );
    b.pure(
        "Min",
        "Smaller of `a` and `b` (component-wise for vectors).",
        r#""floor": Min(a: "speed", b: 300.0),"#,
        binary(
            &[(F, Op::MinF), (I, Op::MinI), (V, Op::MinV)],
            None,
            "First operand.",
        ),
    );
    b.pure(
        "Max",
        "Larger of `a` and `b` (component-wise for vectors).",
        r#""floor": Max(a: "speed", b: 100.0),"#,
        binary(
            &[(F, Op::MaxF), (I, Op::MaxI), (V, Op::MaxV)],
            None,
            "First operand.",
        ),
    );
    b.pure(
        "Abs",
        "Absolute value (component-wise for vectors).",
        r#""size": Abs(value: "offset"),"#,
        unary(&[(F, Op::AbsF), (I, Op::AbsI), (V, Op::AbsV)], None),
    );
    b.pure(
        "Negate",
        "`−value`.",
        r#""back": Negate(value: "forward"),"#,
        unary(&[(F, Op::NegF), (I, Op::NegI), (V, Op::NegV)], None),
    );
    b.pure(
        "Clamp",
        "`value` limited to `[min, max]` (component-wise for vectors). If `min > max` the \
         result is `max`.",
        r#""z": Clamp(value: "height", min: -30.0, max: 40.0),"#,
        [(F, Op::ClampF), (I, Op::ClampI), (V, Op::ClampV)]
            .iter()
            .map(|&(ty, op)| {
                let (lo, hi) = match ty {
                    F => (Value::Float(0.0), Value::Float(1.0)),
                    I => (Value::Int(0), Value::Int(1)),
                    _ => (Value::Vec3(Vec3::ZERO), Value::Vec3(Vec3::ONE)),
                };
                ov(
                    op,
                    vec![
                        input("value", ty, "The value to limit."),
                        opt("min", lo, "Lower bound."),
                        opt("max", hi, "Upper bound."),
                    ],
                    vec![output("result", ty, "The clamped value.")],
                )
            })
            .collect(),
    );
    for (name, op, doc, example) in [
        (
            "Sin",
            Op::SinF,
            "Sine of an angle in degrees.",
            r#""wave": Sin(value: "phase"),"#,
        ),
        (
            "Cos",
            Op::CosF,
            "Cosine of an angle in degrees.",
            r#""c": Cos(value: "phase"),"#,
        ),
        (
            "Tan",
            Op::TanF,
            "Tangent of an angle in degrees.",
            r#""t": Tan(value: 30.0),"#,
        ),
    ] {
        b.pure(
            name,
            doc,
            example,
            vec![ov(
                op,
                vec![opt("value", f0(), "Angle, degrees.")],
                vec![output("result", F, "The result.")],
            )],
        );
    }
    b.pure(
        "Atan2",
        "Angle of the vector `(x, y)` from the +X axis, degrees in (−180, 180]; 0 for `(0, 0)`.",
        r#""pitch": Atan2(y: "nx", x: "nz"),"#,
        vec![ov(
            Op::Atan2F,
            vec![
                opt("y", f0(), "Y component."),
                opt("x", f0(), "X component."),
            ],
            vec![output("result", F, "Angle, degrees.")],
        )],
    );
    b.pure(
        "Sqrt",
        "Square root; 0 for negative input.",
        r#""r": Sqrt(value: "r2"),"#,
        unary(&[(F, Op::SqrtF)], None),
    );
    b.pure(
        "Pow",
        "`base ^ exponent`.",
        r#""sq": Pow(base: "x", exponent: 2.0),"#,
        vec![ov(
            Op::PowF,
            vec![
                opt("base", f0(), "Base."),
                opt("exponent", Value::Float(1.0), "Exponent."),
            ],
            vec![output("result", F, "The power.")],
        )],
    );
    b.pure(
        "Fract",
        "Fractional part `value − floor(value)`, in [0, 1); wraps a cycle phase.",
        r#""phase": Fract(value: "advanced"),"#,
        unary(&[(F, Op::FractF)], None),
    );
    for (name, op, doc, example) in [
        (
            "Floor",
            Op::FloorF,
            "Largest whole number ≤ value.",
            r#""whole": Floor(value: "x"),"#,
        ),
        (
            "Ceil",
            Op::CeilF,
            "Smallest whole number ≥ value.",
            r#""whole": Ceil(value: "x"),"#,
        ),
        (
            "Round",
            Op::RoundF,
            "Nearest whole number, halves away from zero.",
            r#""whole": Round(value: "x"),"#,
        ),
    ] {
        b.pure(name, doc, example, unary(&[(F, op)], None));
    }
    b.pure(
        "ToInt",
        "Float → Int, truncating towards zero; NaN gives 0, out-of-range saturates.",
        r#""i": ToInt(value: "x"),"#,
        unary(&[(F, Op::ToInt)], Some(I)),
    );
    b.pure(
        "ToFloat",
        "Int → Float (also done implicitly when an Int feeds a Float pin).",
        r#""x": ToFloat(value: "i"),"#,
        unary(&[(I, Op::ToFloat)], Some(F)),
    );
    b.pure(
        "Lerp",
        "`a + (b − a)·alpha`; alpha is not clamped.",
        r#""mid": Lerp(a: "start", b: "end", alpha: 0.5),"#,
        [(F, Op::LerpF), (V, Op::LerpV)]
            .iter()
            .map(|&(ty, op)| {
                ov(
                    op,
                    vec![
                        opt("a", zero_of(ty), "Value at alpha 0."),
                        opt("b", zero_of(ty), "Value at alpha 1."),
                        opt("alpha", f0(), "Blend, 0..1 (not clamped)."),
                    ],
                    vec![output("result", ty, "The blend.")],
                )
            })
            .collect(),
    );
    b.pure(
        "Remap",
        "Maps `value` linearly from `[in_min, in_max]` to `[out_min, out_max]`; with \
         `clamp` the result stays inside the output range. A zero-width input range gives \
         `out_min`.",
        r#""lift": Remap(value: "speed", in_min: 0.0, in_max: 500.0, out_min: 0.0, out_max: 10.0),"#,
        vec![ov(
            Op::RemapF,
            vec![
                input("value", F, "The value to map."),
                opt("in_min", f0(), "Input range start."),
                opt("in_max", Value::Float(1.0), "Input range end."),
                opt("out_min", f0(), "Output range start."),
                opt("out_max", Value::Float(1.0), "Output range end."),
                opt("clamp", Value::Bool(true), "Keep the result inside the output range."),
            ],
            vec![output("result", F, "The mapped value.")],
        )],
    );
    b.pure(
        "SmoothStep",
        "Eases from 0 to 1 as `value` goes from `min` to `max`: `t²·(3 − 2t)` with `t` the \
         clamped linear position in the range (GLSL's `smoothstep`), so the result and its \
         slope have no step at either end. `min > max` runs it backwards; a zero-width \
         range or a NaN gives 0.",
        r#""ease": SmoothStep(value: "alpha", min: 0.0, max: 0.3),"#,
        vec![ov(
            Op::SmoothStepF,
            vec![
                input("value", F, "The value to ease."),
                opt("min", f0(), "Where the result starts rising from 0."),
                opt("max", Value::Float(1.0), "Where the result reaches 1."),
            ],
            vec![output("result", F, "The eased weight, 0..1.")],
        )],
    );

    b.category = "Logic";
    for (name, op, doc, example) in [
        (
            "And",
            Op::And,
            "`a and b`.",
            r#""both": And(a: "planted", b: "moving"),"#,
        ),
        (
            "Or",
            Op::Or,
            "`a or b`.",
            r#""either": Or(a: "left_hit", b: "right_hit"),"#,
        ),
        (
            "Xor",
            Op::Xor,
            "`a xor b`: true when exactly one is true.",
            r#""one": Xor(a: "left_planted", b: "right_planted"),"#,
        ),
    ] {
        b.pure(
            name,
            doc,
            example,
            vec![ov(
                op,
                vec![
                    opt("a", Value::Bool(false), "First operand."),
                    opt("b", Value::Bool(false), "Second operand."),
                ],
                vec![output("result", B, "The result.")],
            )],
        );
    }
    b.pure(
        "Not",
        "`not value`.",
        r#""swinging": Not(value: "locked"),"#,
        unary(&[(B, Op::Not)], None),
    );
    let eq_types = [Elem::Float, Elem::Int, Elem::Bool, Elem::Bone];
    b.pure(
        "Equals",
        "`a == b` (exact for floats). Bones compare by index.",
        r#""is_left": Equals(a: "index", b: 0),"#,
        eq_types
            .iter()
            .map(|&e| {
                let ty = e.scalar();
                ov(
                    Op::Equals(e),
                    vec![
                        opt("a", zero_of(ty), "First operand."),
                        opt("b", zero_of(ty), "Second operand."),
                    ],
                    vec![output("result", B, "The result.")],
                )
            })
            .collect(),
    );
    b.pure(
        "NotEquals",
        "`a != b`.",
        r#""is_right": NotEquals(a: "index", b: 0),"#,
        eq_types
            .iter()
            .map(|&e| {
                let ty = e.scalar();
                ov(
                    Op::NotEquals(e),
                    vec![
                        opt("a", zero_of(ty), "First operand."),
                        opt("b", zero_of(ty), "Second operand."),
                    ],
                    vec![output("result", B, "The result.")],
                )
            })
            .collect(),
    );
    for (name, fop, iop, doc, example) in [
        (
            "Less",
            Op::LessF,
            Op::LessI,
            "`a < b`.",
            r#""swinging": Less(a: "phase", b: var("SwingTimeAsAPercent")),"#,
        ),
        (
            "LessEqual",
            Op::LessEqualF,
            Op::LessEqualI,
            "`a <= b`.",
            r#""low": LessEqual(a: "height", b: 1.5),"#,
        ),
        (
            "Greater",
            Op::GreaterF,
            Op::GreaterI,
            "`a > b`.",
            r#""locked": Greater(a: "phase", b: var("SwingTimeAsAPercent")),"#,
        ),
        (
            "GreaterEqual",
            Op::GreaterEqualF,
            Op::GreaterEqualI,
            "`a >= b`.",
            r#""late": GreaterEqual(a: "half_phase", b: 0.4),"#,
        ),
    ] {
        b.pure(
            name,
            doc,
            example,
            binary(&[(F, fop), (I, iop)], Some(B), "First operand."),
        );
    }
    b.pure(
        "Select",
        "`if_true` when `condition` holds, else `if_false` (RigVM's pure *If*). Both inputs \
         are evaluated.",
        r#""axis": Select(condition: "is_left", if_true: (-1.0, 0.0, 0.0), if_false: (1.0, 0.0, 0.0)),"#,
        ValueType::ALL
            .iter()
            .filter(|t| **t != ValueType::Name)
            .map(|&ty| {
                ov(
                    Op::Select(ty),
                    vec![
                        input("condition", B, "Which input to pass on."),
                        opt("if_true", zero_of(ty), "Result when the condition is true."),
                        opt("if_false", zero_of(ty), "Result when it is false."),
                    ],
                    vec![output("result", ty, "The selected value.")],
                )
            })
            .collect(),
    );

    b.category = "Vector";
    let v0 = || Value::Vec3(Vec3::ZERO);
    b.pure(
        "Scale",
        "`value · factor`.",
        r#""half": Scale(value: "stride", factor: 0.5),"#,
        vec![ov(
            Op::ScaleV,
            vec![
                opt("value", v0(), "The vector."),
                opt("factor", Value::Float(1.0), "Multiplier."),
            ],
            vec![output("result", V, "The scaled vector.")],
        )],
    );
    b.pure(
        "BSpline",
        "Position and tangent at `u` on a curve through `points` (the seed's \"Spline From \
         Points\" + \"Position From Spline\"). `BSpline`: a clamped uniform B-spline of \
         degree min(3, N − 1) — it starts at the first point, ends at the last, and is pulled \
         towards (not through) the others; `u` is the knot parameter, the N − k spans equally \
         long in `u` (not in arc length). `CatmullRom`: a uniform Catmull-Rom curve through \
         every point, point i at u = i/(N − 1). `u` is clamped to [0, 1] (NaN → 0). No points: \
         zero; one point: that point with a zero tangent.",
        r#""arc": BSpline(points: var("SwingPoints"), u: "alpha"),"#,
        vec![ov(
            Op::Spline,
            vec![
                input(
                    "points",
                    ValueType::Array(Elem::Vec3),
                    "Control points, rig space, cm.",
                ),
                opt("u", f0(), "Curve parameter, 0..1."),
                choice("mode", &["BSpline", "CatmullRom"], 0, "Which curve."),
            ],
            vec![
                output("position", V, "Point on the curve, cm."),
                output("tangent", V, "Derivative with respect to u, cm per unit u."),
            ],
        )],
    );
    b.pure(
        "ClampLength",
        "`value` with its length limited to `[min, max]` cm, direction kept. A zero vector \
         has no direction and stays zero.",
        r#""step": ClampLength(value: "delta", max: 30.0),"#,
        vec![ov(
            Op::ClampLength,
            vec![
                input("value", V, "The vector."),
                opt("min", f0(), "Shortest length, cm."),
                opt("max", Value::Float(1.0e9), "Longest length, cm."),
            ],
            vec![output("result", V, "The clamped vector.")],
        )],
    );
    b.pure(
        "ClampSpatially",
        "Keeps `point` between `min_radius` and `max_radius` cm from `center`: too far is \
         pulled in, too close pushed out, along the line to the centre. A point exactly at \
         the centre is returned unchanged.",
        r#""kept": ClampSpatially(point: "locked_foot", center: "pelvis_pos", max_radius: 100.0),"#,
        vec![ov(
            Op::ClampSpatially,
            vec![
                input("point", V, "The point, rig space, cm."),
                input("center", V, "Sphere centre, rig space, cm."),
                opt("min_radius", f0(), "Inner radius, cm."),
                opt("max_radius", Value::Float(100.0), "Outer radius, cm."),
            ],
            vec![output("result", V, "The clamped point.")],
        )],
    );
    b.pure(
        "Length",
        "Euclidean length `|value|`, centimetres for positions.",
        r#""speed": Length(value: var("RigSpaceVelocity")),"#,
        unary(&[(V, Op::LengthV)], Some(F)),
    );
    b.pure(
        "Distance",
        "`|a − b|`.",
        r#""gap": Distance(a: "left", b: "right"),"#,
        binary(&[(V, Op::DistanceV)], Some(F), "First point."),
    );
    b.pure(
        "Unit",
        "`value / |value|`; a zero (or non-finite-length) vector gives the zero vector. \
         For rotations, the normalised quaternion (identity for a zero quaternion).",
        r#""dir": Unit(value: "velocity"),"#,
        {
            let mut o = unary(&[(V, Op::UnitV)], None);
            o.push(ov(
                Op::UnitQ,
                vec![opt("value", Value::Quat(Quat::IDENTITY), "The rotation.")],
                vec![output("result", Q, "Unit quaternion.")],
            ));
            o
        },
    );
    b.pure(
        "Dot",
        "`a · b`.",
        r#""forward_speed": Dot(a: "velocity", b: (0.0, 1.0, 0.0)),"#,
        binary(&[(V, Op::DotV)], Some(F), "First vector."),
    );
    b.pure(
        "Cross",
        "`a × b` (right-handed: X × Y = Z).",
        r#""side": Cross(a: "forward", b: (0.0, 0.0, 1.0)),"#,
        binary(&[(V, Op::CrossV)], None, "First vector."),
    );
    b.pure(
        "MakeVector",
        "`(x, y, z)`.",
        r#""offset": MakeVector(z: "bob"),"#,
        vec![ov(
            Op::MakeVector,
            vec![
                opt("x", f0(), "X (left), cm."),
                opt("y", f0(), "Y (forward), cm."),
                opt("z", f0(), "Z (up), cm."),
            ],
            vec![output("result", V, "The vector.")],
        )],
    );
    b.pure(
        "BreakVector",
        "The components of a vector: outputs `x`, `y`, `z` (link them as `\"node.x\"`).",
        r#""parts": BreakVector(value: "normal"),"#,
        vec![ov(
            Op::BreakVector,
            vec![input("value", V, "The vector.")],
            vec![
                output("x", F, "X component."),
                output("y", F, "Y component."),
                output("z", F, "Z component."),
            ],
        )],
    );

    b.category = "Rotation";
    b.pure(
        "QuatFromAxisAngle",
        "Rotation of `angle` degrees about `axis` (right-hand rule). A zero axis gives the identity.",
        r#""yaw": QuatFromAxisAngle(axis: (0.0, 0.0, 1.0), angle: "yaw_degrees"),"#,
        vec![ov(
            Op::QuatFromAxisAngle,
            vec![opt("axis", Value::Vec3(Vec3::Z), "Rotation axis (normalised internally)."), opt("angle", f0(), "Angle, degrees.")],
            vec![output("result", Q, "The rotation.")],
        )],
    );
    b.pure(
        "QuatFromEuler",
        "Rotation from Euler angles in degrees. Order XYZ applies X first, then Y, then Z \
         about the rig axes (`q = Rz·Ry·Rx`); ZYX the reverse. See docs/conventions.md.",
        r#""tilt": QuatFromEuler(euler: (0.0, -15.0, 0.0)),"#,
        vec![ov(
            Op::QuatFromEuler,
            vec![
                opt("euler", v0(), "(x, y, z) angles, degrees."),
                choice("order", EULER_ORDERS, 0, "Which rotation applies first."),
            ],
            vec![output("result", Q, "The rotation.")],
        )],
    );
    b.pure(
        "EulerFromQuat",
        "Euler angles in degrees of a rotation (inverse of QuatFromEuler). The middle angle \
         is in [−90, 90], the others in (−180, 180].",
        r#""angles": EulerFromQuat(value: "rotation"),"#,
        vec![ov(
            Op::EulerFromQuat,
            vec![
                input("value", Q, "The rotation."),
                choice("order", EULER_ORDERS, 0, "Which rotation applies first."),
            ],
            vec![output("result", V, "(x, y, z) angles, degrees.")],
        )],
    );
    b.pure(
        "Inverse",
        "The inverse rotation or transform. A zero scale axis inverts to zero, not infinity.",
        r#""to_local": Inverse(value: "root"),"#,
        vec![
            ov(
                Op::InverseQ,
                vec![input("value", Q, "The rotation.")],
                vec![output("result", Q, "Its inverse.")],
            ),
            ov(
                Op::InverseT,
                vec![input("value", T, "The transform.")],
                vec![output("result", T, "Its inverse.")],
            ),
        ],
    );
    b.pure(
        "Slerp",
        "Shortest-path spherical interpolation from `a` (alpha 0) to `b` (alpha 1).",
        r#""half": Slerp(a: "left_rot", b: "right_rot", alpha: 0.5),"#,
        vec![ov(
            Op::SlerpQ,
            vec![
                opt("a", Value::Quat(Quat::IDENTITY), "Rotation at alpha 0."),
                opt("b", Value::Quat(Quat::IDENTITY), "Rotation at alpha 1."),
                opt("alpha", f0(), "Blend, 0..1."),
            ],
            vec![output("result", Q, "The blend, normalised.")],
        )],
    );
    b.pure(
        "RotateVector",
        "`rotation · vector`.",
        r#""forward": RotateVector(rotation: "facing", vector: (0.0, 1.0, 0.0)),"#,
        vec![ov(
            Op::RotateVector,
            vec![
                opt("rotation", Value::Quat(Quat::IDENTITY), "The rotation."),
                opt("vector", v0(), "The vector."),
            ],
            vec![output("result", V, "The rotated vector.")],
        )],
    );

    b.pure(
        "QuatScale",
        "Scales a rotation's angle about its own axis, along the shortest path: \
         `scale` 0.5 is half the rotation, −1 its inverse (the seed's `quat_scale`).",
        r#""counter": QuatScale(rotation: "pelvis_twist", scale: -0.667),"#,
        vec![ov(
            Op::QuatScale,
            vec![
                input("rotation", Q, "The rotation."),
                opt("scale", Value::Float(1.0), "Angle multiplier."),
            ],
            vec![output("result", Q, "The scaled rotation.")],
        )],
    );
    b.pure(
        "FindQuatBetween",
        "The shortest rotation taking direction `from` to direction `to` (lengths ignored). \
         A zero vector gives the identity; opposite directions give 180° about an axis \
         perpendicular to `from` (`from × X`, or `from × Y` when `from` is along X).",
        r#""facing": FindQuatBetween(from: (0.0, 1.0, 0.0), to: "velocity"),"#,
        vec![ov(
            Op::FindQuatBetween,
            vec![
                input("from", V, "Start direction."),
                input("to", V, "End direction."),
            ],
            vec![output("result", Q, "Rotation with `result · from ∥ to`.")],
        )],
    );

    b.category = "Transform";
    b.pure(
        "MakeTransform",
        "Transform from translation (cm), rotation and scale.",
        r#""target": MakeTransform(translation: "p", rotation: "r"),"#,
        vec![ov(
            Op::MakeTransform,
            vec![
                opt("translation", v0(), "Translation, cm."),
                opt("rotation", Value::Quat(Quat::IDENTITY), "Rotation."),
                opt("scale", Value::Vec3(Vec3::ONE), "Scale per axis."),
            ],
            vec![output("result", T, "The transform.")],
        )],
    );
    b.pure(
        "BreakTransform",
        "Parts of a transform: outputs `translation`, `rotation`, `scale`.",
        r#""foot": BreakTransform(value: "foot_global"),"#,
        vec![ov(
            Op::BreakTransform,
            vec![input("value", T, "The transform.")],
            vec![
                output("translation", V, "Translation, cm."),
                output("rotation", Q, "Rotation."),
                output("scale", V, "Scale per axis."),
            ],
        )],
    );
    b.pure(
        "MakeRelative",
        "`global` expressed in `parent`'s space: the `local` with `parent · local = global`, for any \
         non-zero scale (`parent⁻¹ · global` when `parent`'s scale is uniform; see docs/conventions.md).",
        r#""local": MakeRelative(global: "foot", parent: "root"),"#,
        vec![ov(
            Op::MakeRelative,
            vec![
                input("global", T, "The transform, in the common space."),
                input("parent", T, "The reference, in the same space."),
            ],
            vec![output("result", T, "`global` relative to `parent`.")],
        )],
    );
    b.pure(
        "MakeAbsolute",
        "`local` placed under `parent`: `parent · local`.",
        r#""world": MakeAbsolute(local: "offset", parent: "root"),"#,
        vec![ov(
            Op::MakeAbsolute,
            vec![
                input("local", T, "The transform relative to parent."),
                input("parent", T, "The parent."),
            ],
            vec![output("result", T, "`parent · local`.")],
        )],
    );
    b.pure(
        "TransformPoint",
        "`transform` applied to a point: `t + r·(s ⊙ point)`.",
        r#""world_point": TransformPoint(transform: "root", point: (0.0, 0.0, 0.0)),"#,
        vec![ov(
            Op::TransformPoint,
            vec![
                input("transform", T, "The transform."),
                opt("point", v0(), "The point, cm."),
            ],
            vec![output("result", V, "The transformed point, cm.")],
        )],
    );
    b.pure(
        "TransformVector",
        "`transform` applied to a direction (rotation and scale, no translation).",
        r#""dir": TransformVector(transform: "root", vector: (0.0, 1.0, 0.0)),"#,
        vec![ov(
            Op::TransformVector,
            vec![
                input("transform", T, "The transform."),
                opt("vector", v0(), "The direction."),
            ],
            vec![output("result", V, "The transformed direction.")],
        )],
    );

    b.pure(
        "RotateAroundPoint",
        "Rotates a transform about a pivot: translation `R·(t − p) + p`, rotation `R·r` \
         (applied after the transform's own rotation), scale kept. Foot roll uses it to \
         turn the foot about its heel, ball or toe tip.",
        r#""rolled": RotateAroundPoint(transform: "foot", pivot: "ball_pivot", rotation: "pitch"),"#,
        vec![ov(
            Op::RotateAroundPoint,
            vec![
                input("transform", T, "The transform to move, rig space."),
                input("pivot", V, "Point to rotate about, rig space, cm."),
                input("rotation", Q, "Rotation applied about the pivot (rig axes)."),
            ],
            vec![output("result", T, "The rotated transform.")],
        )],
    );
    b.pure(
        "InterpolateTransform",
        "Blend of two transforms: lerp translation and scale, shortest-path slerp rotation. \
         `alpha` is not clamped for translation and scale; NaN gives `a`.",
        r#""blend": InterpolateTransform(a: "start", b: "end", alpha: "t"),"#,
        vec![ov(
            Op::InterpolateTransform,
            vec![
                input("a", T, "Transform at alpha 0."),
                input("b", T, "Transform at alpha 1."),
                opt("alpha", f0(), "Blend, 0..1."),
            ],
            vec![output("result", T, "The blend.")],
        )],
    );
    b.pure(
        "AimMath",
        "Rotates a transform by the shortest rotation that points its local `axis` at the \
         target — a rig-space direction or a point (`mode`) — blended by `weight`. \
         Translation and scale are kept. A zero axis or direction changes nothing.",
        r#""aimed": AimMath(transform: "head", axis: (0.0, 1.0, 0.0), target: "look_at", mode: Location),"#,
        vec![ov(
            Op::AimMath,
            vec![
                input("transform", T, "The transform to rotate, rig space."),
                opt("axis", Value::Vec3(Vec3::Y), "The transform's local axis to aim."),
                input("target", V, "Direction (rig space) or point (rig space, cm)."),
                choice("mode", &["Direction", "Location"], 0, "How to read `target`."),
                opt("weight", Value::Float(1.0), "0 = unchanged, 1 = fully aimed (clamped)."),
            ],
            vec![output("result", T, "The aimed transform.")],
        )],
    );
    b.pure(
        "AlignToNormal",
        "Tilts a transform so its local `axis` (default up) lines up with a surface normal, \
         by the shortest rotation (its yaw about the normal is kept), blended by `weight`. \
         A zero normal changes nothing.",
        r#""on_slope": AlignToNormal(transform: "foot", normal: "ground.normal"),"#,
        vec![ov(
            Op::AlignToNormal,
            vec![
                input("transform", T, "The transform to tilt, rig space."),
                opt(
                    "axis",
                    Value::Vec3(Vec3::Z),
                    "The transform's local axis to align.",
                ),
                input("normal", V, "Surface normal, rig space."),
                opt(
                    "weight",
                    Value::Float(1.0),
                    "0 = unchanged, 1 = fully aligned (clamped).",
                ),
            ],
            vec![output("result", T, "The aligned transform.")],
        )],
    );

    b.category = "Hierarchy";
    b.pure(
        "GetTransform",
        "A bone's transform in rig space (`Global`) or relative to its parent (`Local`); \
         with `initial` the rest pose's. No bone gives the identity.",
        r#""pelvis": GetTransform(bone: bone("pelvis"), space: Global, initial: true),"#,
        vec![ov(
            Op::GetTransform,
            vec![
                input("bone", BONE, "The bone."),
                choice(
                    "space",
                    SPACES,
                    0,
                    "Global = rig space; Local = relative to the parent.",
                ),
                opt(
                    "initial",
                    Value::Bool(false),
                    "Read the rest (initial) pose instead of the current one.",
                ),
            ],
            vec![output("result", T, "The transform (cm).")],
        )],
    );
    b.node(
        "SetTransform",
        Effect::Mutating,
        "Writes a bone's transform, blended from the current one by `weight` (lerp \
         translation and scale, slerp rotation). In `Global` space with `propagate` the \
         children move along (RigVM's *Propagate to Children*); without it they keep their \
         rig-space transforms. No bone: nothing happens.",
        r#"SetTransform(bone: bone("pelvis"), value: "bobbed", space: Global),"#,
        vec![ov(
            Op::SetTransform,
            vec![
                input("bone", BONE, "The bone."),
                input("value", T, "The new transform, in `space` (cm)."),
                choice(
                    "space",
                    SPACES,
                    0,
                    "Global = rig space; Local = relative to the parent.",
                ),
                opt("propagate", Value::Bool(true), "Children follow the bone."),
                opt(
                    "weight",
                    Value::Float(1.0),
                    "Blend from the current transform, 0..1 (clamped).",
                ),
            ],
            vec![],
        )],
    );
    b.pure(
        "GetParent",
        "A bone's parent; no bone for a root or for no bone.",
        r#""calf": GetParent(bone: "foot"),"#,
        vec![ov(
            Op::GetParent,
            vec![input("bone", BONE, "The child.")],
            vec![output("result", BONE, "Its parent.")],
        )],
    );
    b.pure(
        "FindBones",
        "The descendants of `root` (not `root` itself), in hierarchy order, whose name \
         contains `contains` and not `excludes` (case-insensitive; an empty `excludes` \
         excludes nothing). Compares strings: use it in `construction`, not every frame.",
        r#""feet": FindBones(root: bone("root"), contains: name("foot"), excludes: name("ik")),"#,
        vec![ov(
            Op::FindBones,
            vec![
                input("root", BONE, "Where to search below."),
                input("contains", ValueType::Name, "Text the name must contain."),
                opt(
                    "excludes",
                    Value::Name(String::new()),
                    "Text the name must not contain.",
                ),
            ],
            vec![output(
                "result",
                ValueType::Array(Elem::Bone),
                "Matching bones.",
            )],
        )],
    );
    b.node(
        "TwoBoneIK",
        Effect::Mutating,
        "RigVM's Basic IK on the chain `bone_a` → `bone_b` → `effector` (e.g. thigh → calf → \
         foot): rotates A and B (global, children follow) so the effector reaches `target`, \
         bending towards the pole. `primary_axis` is the local axis of A and B that points \
         down the chain ((−1, 0, 0) for the mannequin's left limbs, (1, 0, 0) for the right), \
         `secondary_axis` the local axis turned towards the pole ((0, 1, 0) left, (0, −1, 0) \
         right). Bone lengths come from the current pose. A target out of reach straightens \
         the chain towards it (no NaN); a target at the root keeps the current direction; a \
         pole along the chain falls back to the current knee offset, then to A's secondary \
         axis. With `stretch` the bones lengthen linearly from `stretch_start`·reach up to \
         `stretch_max` (Unreal's ramp). A missing bone or a NaN target changes nothing \
         (`reached` false, `distance` infinite).",
        r#"TwoBoneIK(bone_a: bone("thigh_l"), bone_b: bone("calf_l"), effector: bone("foot_l"), target: "foot_target", primary_axis: (-1.0, 0.0, 0.0), pole: "knee_pole"),"#,
        vec![ov(
            Op::TwoBoneIK,
            vec![
                input("bone_a", BONE, "Chain root (thigh, upper arm)."),
                input("bone_b", BONE, "Middle joint (calf, forearm)."),
                input("effector", BONE, "End of the chain (foot, hand)."),
                input("target", T, "Where the effector should be, rig space."),
                opt(
                    "primary_axis",
                    Value::Vec3(Vec3::NEG_X),
                    "Local axis of A and B along the chain (default: the mannequin's left limbs; (1, 0, 0) on the right).",
                ),
                opt(
                    "secondary_axis",
                    Value::Vec3(Vec3::Y),
                    "Local axis of A and B towards the pole (default: left limbs; (0, −1, 0) on the right).",
                ),
                opt("pole", Value::Vec3(Vec3::Y), "Pole direction (rig space) or location (rig space, cm)."),
                choice("pole_kind", &["Direction", "Location"], 0, "How to read `pole`."),
                opt("weight", Value::Float(1.0), "Blend from the current pose, 0..1."),
                opt("stretch", Value::Bool(false), "Allow the bones to lengthen."),
                opt("stretch_start", Value::Float(0.75), "Reach ratio where stretching starts."),
                opt("stretch_max", Value::Float(1.25), "Largest length scale."),
                opt("set_effector_rotation", Value::Bool(true), "Give the effector the target's rotation."),
            ],
            vec![
                output("reached", B, "The effector is within 1e-3 cm of the target."),
                output("distance", F, "Effector to target after the solve, cm."),
            ],
        )],
    );
    b.pure(
        "DeltaTime",
        "Seconds since the previous frame, as given by the host (sanitised: never negative \
         or NaN; 0 during construction).",
        r#""dt": DeltaTime(),"#,
        vec![ov(
            Op::DeltaTime,
            vec![],
            vec![output("result", F, "Frame time, s.")],
        )],
    );
    b.pure(
        "WorldTransform",
        "This frame's component-to-world transform: where the host placed the character.",
        r#""root_world": WorldTransform(),"#,
        vec![ov(
            Op::WorldTransform,
            vec![],
            vec![output("result", T, "Component to world, cm.")],
        )],
    );

    b.category = "World";
    let trace_outputs = || {
        vec![
            output("hit", B, "Whether anything was hit."),
            output(
                "point",
                V,
                "Contact point, rig space, cm (the end point on a miss).",
            ),
            output(
                "normal",
                V,
                "Surface normal, rig space, unit (+Z on a miss).",
            ),
            output(
                "distance",
                F,
                "Distance travelled to the hit, cm (the full length on a miss).",
            ),
        ]
    };
    b.pure(
        "LineTrace",
        "Asks the host world for the first hit along the segment `start → end` (rig space; \
         converted to world space with this frame's component-to-world transform and back). \
         A host with no geometry always misses.",
        r#""ground": LineTrace(start: "above", end: "below"),"#,
        vec![ov(
            Op::LineTrace,
            vec![
                input("start", V, "Segment start, rig space, cm."),
                input("end", V, "Segment end, rig space, cm."),
            ],
            trace_outputs(),
        )],
    );
    b.pure(
        "SphereTrace",
        "Sweeps a sphere of `radius` from `start` to `end` (rig space) through the host world \
         and reports the first hit; `point` is where the sphere touches the surface.",
        r#""land": SphereTrace(start: "above", end: "below", radius: 5.0),"#,
        vec![ov(
            Op::SphereTrace,
            vec![
                input("start", V, "Sweep start (sphere centre), rig space, cm."),
                input("end", V, "Sweep end (sphere centre), rig space, cm."),
                opt(
                    "radius",
                    Value::Float(5.0),
                    "Sphere radius, cm (negative counts as 0).",
                ),
            ],
            trace_outputs(),
        )],
    );

    b.category = "Smoothing";
    let speed = |d: f32| {
        opt(
            "speed",
            Value::Float(d),
            "Blend speed k, 1/s: the gap shrinks by e^(−k·dt) per frame.",
        )
    };
    b.pure(
        "VectorLerp",
        "Moves `current` towards `target` frame-rate independently: \
         `current + (target − current)·(1 − e^(−speed·dt))` with this frame's dt — N frames of \
         dt land exactly where one frame of N·dt does. With `max_per_second` > 0 the step is \
         also clamped to `max_per_second·dt` cm (the seed's max-step variant). The seed's own \
         `current + (target − current)·clamp(speed·dt, 0, 1)` depends on the frame rate (at \
         k = 2/s over 1 s: 0.869 of the way at 60 Hz, 0.874 at 30 Hz, all of it at 1 Hz); \
         this node does not. dt = 0 or speed ≤ 0: no motion.",
        r#""smoothed": VectorLerp(current: var("RigSpaceVelocity"), target: "velocity", speed: 6.0),"#,
        vec![ov(
            Op::VectorLerp,
            vec![
                input("current", V, "Value last frame (usually a variable)."),
                input("target", V, "Value to approach."),
                speed(6.0),
                opt("max_per_second", f0(), "Largest step per second, cm/s; 0 = no limit."),
            ],
            vec![output("result", V, "The new value.")],
        )],
    );
    b.pure(
        "FloatLerp",
        "VectorLerp for a float: `current + (target − current)·(1 − e^(−speed·dt))`, frame-rate independent.",
        r#""offset": FloatLerp(current: var("PreviousZTraceOffset"), target: "drop", speed: 5.0),"#,
        vec![ov(
            Op::FloatLerp,
            vec![input("current", F, "Value last frame."), input("target", F, "Value to approach."), speed(6.0)],
            vec![output("result", F, "The new value.")],
        )],
    );
    b.pure(
        "QuatLerp",
        "VectorLerp for a rotation: slerp from `current` towards `target` by `1 − e^(−speed·dt)`, frame-rate independent.",
        r#""facing": QuatLerp(current: var("Facing"), target: "wanted", speed: 6.0),"#,
        vec![ov(
            Op::QuatLerp,
            vec![input("current", Q, "Rotation last frame."), input("target", Q, "Rotation to approach."), speed(6.0)],
            vec![output("result", Q, "The new rotation.")],
        )],
    );
    b.pure(
        "FInterpTo",
        "Unreal's FInterpTo / VInterpTo / RInterpTo: step `(target − current)·clamp(speed·dt, 0, 1)`. \
         Kept for graphs ported from Unreal; it depends on the frame rate — prefer VectorLerp. \
         speed ≤ 0 snaps to the target.",
        r#""foot_z": FInterpTo(current: var("FootOffset"), target: "offset", speed: 20.0),"#,
        [(F, Op::FInterpToF), (V, Op::FInterpToV), (Q, Op::FInterpToQ)]
            .iter()
            .map(|&(ty, op)| {
                ov(
                    op,
                    vec![
                        input("current", ty, "Value last frame."),
                        input("target", ty, "Value to approach."),
                        opt("speed", Value::Float(10.0), "Interp speed, 1/s."),
                    ],
                    vec![output("result", ty, "The new value.")],
                )
            })
            .collect(),
    );
    b.pure(
        "SpringDamper",
        "A critically damped spring following `target`, exact for any dt (closed form), \
         with no overshoot. Its damping rate is y = 2·ln 2 / `half_life`: released at rest, \
         the gap to a still target shrinks as (1 + y·t)·e^(−y·t) — 60 % left after one \
         half_life, 8 % after three. \
         Stateful: each node (per call site) keeps its own position and velocity, starting at \
         rest on the first target it sees, and advances once per frame — reading it from \
         several steps (or loop iterations) in one frame gives the same value. For one spring \
         per array element, keep positions and velocities in array variables instead.",
        r#""pelvis_z": SpringDamper(target: "wanted_z", half_life: 0.15),"#,
        [(F, Op::SpringF), (V, Op::SpringV)]
            .iter()
            .map(|&(ty, op)| Overload {
                state: vec![I, ty, ty],
                ..ov(
                    op,
                    vec![
                        input("target", ty, "Value to follow."),
                        opt(
                            "half_life",
                            Value::Float(0.1),
                            "Seconds to halve the gap (≤ 0 snaps).",
                        ),
                    ],
                    vec![output("value", ty, "The spring's position.")],
                )
            })
            .collect(),
    );

    b.category = "Locomotion";
    b.pure(
        "GetMovementAngleOffset",
        "The yaw (degrees) the legs step towards, for 8-direction movement: the Z angle of the \
         rotation from +Y to the velocity's XY direction, backward diagonals folded (beyond \
         ±`fold_threshold` it adds or subtracts 180 so walking backwards steps backwards), \
         blended from `current` at `speed` (frame-rate independent) — or at `jump_speed` when \
         the change exceeds `jump_threshold` and the feet are not at the start of a step \
         (fract(2·master_cycle) ≥ `step_start_gate`), which keeps legs from crossing on a \
         sudden reversal. Zero velocity keeps `current`.",
        r#""mao": GetMovementAngleOffset(velocity: var("RigSpaceVelocity"), current: var("MovementAngleOffset"), master_cycle: var("MasterCyclePercent")),"#,
        vec![ov(
            Op::MovementAngleOffset,
            vec![
                input("velocity", V, "Rig-space velocity, cm/s."),
                input("current", F, "Offset last frame, degrees."),
                input("master_cycle", F, "Master cycle phase, 0..1."),
                speed(6.0),
                opt("jump_speed", Value::Float(0.2), "Blend speed for large jumps mid-step, 1/s."),
                opt("jump_threshold", Value::Float(90.0), "A change above this is a jump, degrees."),
                opt("fold_threshold", Value::Float(110.0), "Yaw beyond ± this folds by 180, degrees."),
                opt("step_start_gate", Value::Float(0.4), "fract(2·cycle) below this is a step start."),
            ],
            vec![output("result", F, "New offset, degrees.")],
        )],
    );
    b.pure(
        "CalculatePerFootRotationFactor",
        "How much of the movement yaw a foot follows: `positive_factor` when yaw > 0, else `negative_factor`.",
        r#""factor": CalculatePerFootRotationFactor(yaw: "foot_yaw"),"#,
        vec![ov(
            Op::PerFootRotationFactor,
            vec![
                input("yaw", F, "Yaw, degrees."),
                opt("positive_factor", Value::Float(0.5), "Factor for yaw > 0."),
                opt("negative_factor", Value::Float(0.9), "Factor for yaw ≤ 0."),
            ],
            vec![output("result", F, "The factor.")],
        )],
    );
    b.pure(
        "LimitRotationAroundZ",
        "Clamps a rotation's yaw (its twist about Z) to `center_yaw ± limit` degrees and keeps \
         its tilt (swing), so a foot stays aligned with the slope.",
        r#""foot_rot": LimitRotationAroundZ(rotation: "wanted", center_yaw: "mao", limit: 25.0),"#,
        vec![ov(
            Op::LimitRotationAroundZ,
            vec![
                input("rotation", Q, "The rotation."),
                opt(
                    "center_yaw",
                    f0(),
                    "Centre of the allowed yaw range, degrees.",
                ),
                opt(
                    "limit",
                    Value::Float(25.0),
                    "Half width of the range, degrees.",
                ),
            ],
            vec![output("result", Q, "The limited rotation.")],
        )],
    );
    b.pure(
        "FootAvoidance",
        "Keeps a foot from crossing the other: in the movement frame (Mv = Rz(offset)·Y, \
         Side = Rz(90°)·Mv, which points to the character's right), the left foot's side \
         coordinate is at most the other foot's minus `margin`, the right foot's at least plus \
         `margin`; forward and height are kept.",
        r#""avoided": FootAvoidance(ideal: "spline.position", other_foot: "other_platform", movement_offset: var("MovementAngleOffset"), is_left: "is_left"),"#,
        vec![ov(
            Op::FootAvoidance,
            vec![
                input("ideal", V, "Where the foot wants to be, rig space, cm."),
                input("other_foot", V, "The other foot's position, rig space, cm."),
                opt("movement_offset", f0(), "Movement yaw, degrees."),
                input("is_left", B, "True for the left foot."),
                opt("margin", Value::Float(15.0), "Minimum sideways gap, cm."),
            ],
            vec![output("result", V, "The corrected position.")],
        )],
    );
    b.pure(
        "CalculateKneeVector",
        "The knee pole for leg IK: `slerp(platform_rotation, movement_rotation, blend) · \
         (default_knee · scale)`, so knees follow the movement direction a little and crouch \
         poses keep knees apart. `platform_rotation` is the foot platform's rotation in rig \
         axes (identity on flat ground facing forward) — not a foot bone's rotation, whose \
         axes follow the bone. A zero default knee gives zero.",
        r#""pole": CalculateKneeVector(platform_rotation: "platform.rotation", movement_rotation: "mao_rot", default_knee: "knee"),"#,
        vec![ov(
            Op::KneeVector,
            vec![
                input("platform_rotation", Q, "The foot platform's rotation."),
                input("movement_rotation", Q, "Movement yaw as a rotation."),
                input("default_knee", V, "Rest knee vector (calf − midpoint(thigh, foot)), cm."),
                opt("blend", Value::Float(0.25), "0 = platform, 1 = movement."),
                opt("scale", Value::Float(20.0), "Multiplier on the default knee vector."),
            ],
            vec![output("result", V, "Pole vector, rig space.")],
        )],
    );
    b.pure(
        "ArmSwingRotation",
        "The hand's swing pitch about the shoulder, degrees (the seed's \
         GetArmMotionEffectorRotationAmount): `sin(360°·fract(cycle + phase_offset)) · \
         clamp(v̂·(quat_scale(movement, direction_scale)·Y), direction_min, direction_max) · \
         remap(|v|, 0..speed_max → 0..swing_max) · clamp(|v·(0, lateral_scale, 0)|, lateral_min, \
         lateral_max) + remap(|v|, 0..speed_max → 0..base_max)`. Walking backwards swings less. \
         The lateral term multiplies the velocity in cm/s, as the seed does, so it is 1 for any \
         forward speed above lateral_max / lateral_scale and only bites when moving almost \
         purely sideways.",
        r#""swing": ArmSwingRotation(per_foot_cycle: "cycle", velocity: var("SlowVelocity"), movement_rotation: "mao_rot"),"#,
        vec![ov(
            Op::ArmSwingRotation,
            vec![
                input("per_foot_cycle", F, "The opposite foot's cycle phase, 0..1."),
                input("velocity", V, "Rig-space velocity, cm/s."),
                input("movement_rotation", Q, "Movement yaw as a rotation."),
                opt("phase_offset", Value::Float(0.15), "Phase lead of the arm, cycles."),
                opt("direction_scale", Value::Float(0.4), "quat_scale applied to the movement rotation."),
                opt("direction_min", Value::Float(-0.5), "Lower clamp of the direction factor."),
                opt("direction_max", Value::Float(1.0), "Upper clamp of the direction factor."),
                opt("speed_max", Value::Float(300.0), "Speed of the full swing, cm/s."),
                opt("swing_max", Value::Float(50.0), "Swing amplitude at speed_max, degrees."),
                opt("base_max", Value::Float(15.0), "Constant forward pitch at speed_max, degrees."),
                opt("lateral_scale", Value::Float(0.4), "Y factor in the lateral term."),
                opt("lateral_min", Value::Float(0.4), "Lower clamp of the lateral term."),
                opt("lateral_max", Value::Float(1.0), "Upper clamp of the lateral term."),
            ],
            vec![output("result", F, "Pitch, degrees.")],
        )],
    );
    b.pure(
        "ClavicleOffset",
        "Clavicle bob, cm: `sin(720°·(master_cycle − 0.25)) · remap(speed, 0..speed_max → 0..amplitude_max)` (twice per cycle).",
        r#""bob": ClavicleOffset(master_cycle: var("MasterCyclePercent"), speed: "speed"),"#,
        vec![ov(
            Op::ClavicleOffset,
            vec![
                input("master_cycle", F, "Master cycle phase, 0..1."),
                input("speed", F, "Speed, cm/s."),
                opt("speed_max", Value::Float(300.0), "Speed of the full bob, cm/s."),
                opt("amplitude_max", Value::Float(1.5), "Bob at speed_max, cm."),
            ],
            vec![output("result", F, "Z offset, cm.")],
        )],
    );
    b.pure(
        "PelvisLean",
        "Forward lean from velocity: `pitch = remap(|v|, 0..speed_max → 0..pitch_max)·(v̂·Y)` \
         degrees about X and `shift = remap(|v|, 0..speed_max → 0..shift_max)·(v̂·Y)` cm along Y.",
        r#""lean": PelvisLean(velocity: var("SlowVelocity")),"#,
        vec![ov(
            Op::PelvisLean,
            vec![
                input("velocity", V, "Rig-space velocity, cm/s."),
                opt(
                    "speed_max",
                    Value::Float(300.0),
                    "Speed of the full lean, cm/s.",
                ),
                opt(
                    "pitch_max",
                    Value::Float(-15.0),
                    "Pitch at speed_max moving forward, degrees.",
                ),
                opt(
                    "shift_max",
                    Value::Float(10.0),
                    "Forward shift at speed_max, cm.",
                ),
            ],
            vec![
                output("pitch", F, "Pitch about X, degrees."),
                output("shift", F, "Shift along Y, cm."),
            ],
        )],
    );
    b.pure(
        "PelvisSideLean",
        "Pelvis roll about Y from the feet's height difference: `remap(height_difference, \
         −range..range → −roll_max..roll_max)` degrees. Positive roll (about +Y) lowers the \
         left hip: with left − right as the difference, the hip drops over the lower foot's \
         opposite side; swap the difference (or negate `roll_max`) for the other sense.",
        r#""roll": PelvisSideLean(height_difference: "dz"),"#,
        vec![ov(
            Op::PelvisSideLean,
            vec![
                input("height_difference", F, "Left foot z − right foot z, cm."),
                opt(
                    "range",
                    Value::Float(60.0),
                    "Difference of the full roll, cm.",
                ),
                opt(
                    "roll_max",
                    Value::Float(15.0),
                    "Roll at the full difference, degrees.",
                ),
            ],
            vec![output("result", F, "Roll about Y, degrees.")],
        )],
    );
    b.pure(
        "FootPivots",
        "Pivot points of foot roll (rig space, cm): fwd = tip_length·unit((ball − foot).xy); \
         ball pivot = (ball.xy, ball.z − ball_drop); tip = ball pivot + fwd; heel = (foot.xy, \
         foot.z − heel_drop) − heel_back·fwd. A ball straight above or below the ankle gives \
         pivots straight below, no NaN.",
        r#""pivots": FootPivots(foot: "ankle", ball: "ball"),"#,
        vec![ov(
            Op::FootPivots,
            vec![
                input("foot", V, "Ankle position, rig space, cm."),
                input("ball", V, "Ball-of-foot position, rig space, cm."),
                opt("tip_length", Value::Float(5.8), "Ball to toe tip, cm."),
                opt(
                    "ball_drop",
                    Value::Float(2.5),
                    "Ball joint above the sole, cm.",
                ),
                opt(
                    "heel_drop",
                    Value::Float(9.0),
                    "Ankle above the heel contact, cm.",
                ),
                opt(
                    "heel_back",
                    Value::Float(0.8),
                    "Heel behind the ankle, in tip_length units.",
                ),
            ],
            vec![
                output("ball_pivot", V, "Ball pivot on the sole, cm."),
                output("tip", V, "Toe tip, cm."),
                output("heel", V, "Heel pivot, cm."),
            ],
        )],
    );
    b.pure(
        "CycleStep",
        "Advances the master cycle phase: `master = fract(master + dt / cycle_length)` while \
         `moving` (a cycle length ≤ 0 or NaN, or dt = 0, does not advance), and a foot's phase \
         `fract(next + foot_offset)`. Like every pure node it is evaluated again by each step \
         that reads it: once `Set(\"Master\", \"cycle.next\")` has run, a later step reading \
         `cycle.per_foot` would advance from the new master again — read the foot phases in \
         the same step, or compute them from the variable with Fract(Add(...)).",
        r#""cycle": CycleStep(master: var("MasterCyclePercent"), cycle_length: var("CycleLength"), moving: "moving"),"#,
        vec![ov(
            Op::CycleStep,
            vec![
                input("master", F, "Master phase last frame, 0..1."),
                input("cycle_length", F, "Seconds per cycle."),
                opt("foot_offset", f0(), "This foot's phase offset, cycles (0.5 for the second foot)."),
                opt("moving", Value::Bool(true), "Advance only while true (no stepping in place)."),
            ],
            vec![output("next", F, "New master phase, 0..1."), output("per_foot", F, "This foot's phase, 0..1.")],
        )],
    );
    b.pure(
        "FootOffsetFromTrace",
        "Standing foot IK: a downward trace from the capsule centre that hit at `distance` \
         gives `half_height − distance` (positive: ground above the capsule bottom); a miss gives 0.",
        r#""offset": FootOffsetFromTrace(hit: "trace.hit", distance: "trace.distance", half_height: 90.0),"#,
        vec![ov(
            Op::FootOffsetFromTrace,
            vec![
                input("hit", B, "Whether the trace hit."),
                input("distance", F, "Trace distance to the hit, cm."),
                input("half_height", F, "Capsule half height, cm."),
            ],
            vec![output("result", F, "Offset, cm.")],
        )],
    );
    b.pure(
        "RotationFromNormal",
        "Foot tilt from a ground normal n (seed 003): `pitch = −atan2(n.x, n.z)` (a tilt about \
         +Y in rig axes) and `roll = atan2(n.y, n.z)` (about +X), degrees, each with the \
         opposite sign to the right-hand rule (the tilt is Ry(−pitch)·Rx(−roll)) — so feed \
         `rotation`, not the angles, to a transform. `rotation` tilts +Z onto n with the \
         foot's yaw unchanged. Zero or NaN normal: no tilt.",
        r#""tilt": RotationFromNormal(normal: "trace.normal"),"#,
        vec![ov(
            Op::RotationFromNormal,
            vec![input("normal", V, "Ground normal, rig space.")],
            vec![
                output("pitch", F, "−atan2(n.x, n.z), degrees."),
                output("roll", F, "atan2(n.y, n.z), degrees."),
                output("rotation", Q, "The tilt as a rotation."),
            ],
        )],
    );

    b.category = "Array";
    let arrays =
        |op: fn(Elem) -> Op, f: &dyn Fn(Elem) -> (Vec<PinSpec>, Vec<PinSpec>)| -> Vec<Overload> {
            Elem::ALL
                .iter()
                .map(|&e| {
                    let (i, o) = f(e);
                    ov(op(e), i, o)
                })
                .collect()
        };
    b.pure(
        "At",
        "Element `index` of an array. Out of range (or negative): the element type's zero \
         value (identity, no bone, …).",
        r#""foot": At(array: var("FootArray"), index: "i"),"#,
        arrays(Op::ArrayAt, &|e| {
            (
                vec![
                    input("array", e.array(), "The array."),
                    opt("index", Value::Int(0), "Position, from 0."),
                ],
                vec![output("result", e.scalar(), "The element.")],
            )
        }),
    );
    b.pure(
        "Count",
        "Number of elements.",
        r#""n": Count(array: var("FootArray")),"#,
        arrays(Op::ArrayCount, &|e| {
            (
                vec![input("array", e.array(), "The array.")],
                vec![output("result", I, "Element count.")],
            )
        }),
    );
    b.node(
        "SetAt",
        Effect::Mutating,
        "Overwrites element `index` of an array variable. Out of range: nothing happens.",
        r#"SetAt(array: var("IsFootLockedArray"), index: "i", value: true),"#,
        arrays(Op::ArraySetAt, &|e| {
            (
                vec![
                    target("array", e.array(), "The array variable."),
                    opt("index", Value::Int(0), "Position, from 0."),
                    input("value", e.scalar(), "The new element."),
                ],
                vec![],
            )
        }),
    );
    b.node(
        "Append",
        Effect::Mutating,
        "Appends an element to an array variable (RigVM's *Array Add*). Memory grows only \
         until the largest size seen, so a Reset/Append pattern stops allocating after warm-up.",
        r#"Append(array: var("LockedFootLocationArray"), value: "locked"),"#,
        arrays(Op::ArrayAdd, &|e| {
            (
                vec![
                    target("array", e.array(), "The array variable."),
                    input("value", e.scalar(), "The new element."),
                ],
                vec![],
            )
        }),
    );
    b.node(
        "Reset",
        Effect::Mutating,
        "Empties an array variable (keeps its memory).",
        r#"Reset(array: var("FootArray")),"#,
        arrays(Op::ArrayReset, &|e| {
            (
                vec![target("array", e.array(), "The array variable.")],
                vec![],
            )
        }),
    );

    b.category = "Debug";
    let color = |c: Vec3| opt("color", Value::Vec3(c), "RGB colour, 0..1 per channel.");
    b.node(
        "DrawPoint",
        Effect::Mutating,
        "Draws a point (rig space). Free when the host asked for no debug drawing.",
        r#"DrawPoint(position: "ball_pivot", size: 4.0, color: (1.0, 0.0, 0.0)),"#,
        vec![ov(
            Op::DrawPoint,
            vec![
                input("position", V, "Where, cm, rig space."),
                opt("size", Value::Float(2.0), "Diameter, cm."),
                color(Vec3::ONE),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawLine",
        Effect::Mutating,
        "Draws a segment (rig space). Free when the host asked for no debug drawing.",
        r#"DrawLine(start: "pelvis_pos", end: "arrow_tip", color: (0.0, 1.0, 0.0)),"#,
        vec![ov(
            Op::DrawLine,
            vec![
                input("start", V, "First end, cm, rig space."),
                input("end", V, "Second end, cm, rig space."),
                opt("thickness", Value::Float(0.5), "Width, cm."),
                color(Vec3::ONE),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawArrow",
        Effect::Mutating,
        "Draws an arrow from `start` to `end` (rig space), e.g. a velocity. Free when the \
         host asked for no debug drawing.",
        r#"DrawArrow(start: "pelvis_pos", end: "velocity_tip", color: (1.0, 1.0, 0.0)),"#,
        vec![ov(
            Op::DrawArrow,
            vec![
                input("start", V, "Tail, cm, rig space."),
                input("end", V, "Head, cm, rig space."),
                opt("thickness", Value::Float(0.5), "Width, cm."),
                color(Vec3::new(1.0, 1.0, 0.0)),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawSphere",
        Effect::Mutating,
        "Draws a wire sphere (rig space), e.g. a sphere trace's hit. Free when the host \
         asked for no debug drawing.",
        r#"DrawSphere(center: "hit.point", radius: 5.0),"#,
        vec![ov(
            Op::DrawSphere,
            vec![
                input("center", V, "Centre, cm, rig space."),
                opt("radius", Value::Float(5.0), "Radius, cm."),
                color(Vec3::ONE),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawBox",
        Effect::Mutating,
        "Draws a wire box: `half_extents` along the transform's local axes, placed by \
         `transform` (rig space). Free when the host asked for no debug drawing.",
        r#"DrawBox(transform: "foot", half_extents: (5.0, 12.0, 3.0)),"#,
        vec![ov(
            Op::DrawBox,
            vec![
                input("transform", T, "Box centre and orientation, rig space."),
                opt(
                    "half_extents",
                    Value::Vec3(Vec3::splat(5.0)),
                    "Half size per local axis, cm.",
                ),
                color(Vec3::ONE),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawSpline",
        Effect::Mutating,
        "Draws the curve of a `BSpline` node as `segments` line pieces (rig space). Free \
         when the host asked for no debug drawing.",
        r#"DrawSpline(points: var("SwingPoints"), segments: 16, color: (0.0, 1.0, 1.0)),"#,
        vec![ov(
            Op::DrawSpline,
            vec![
                input(
                    "points",
                    ValueType::Array(Elem::Vec3),
                    "Control points, rig space, cm.",
                ),
                choice("mode", &["BSpline", "CatmullRom"], 0, "Which curve."),
                opt("segments", Value::Int(16), "Line pieces (1..=256)."),
                opt("thickness", Value::Float(0.5), "Width, cm."),
                color(Vec3::new(0.0, 1.0, 1.0)),
            ],
            vec![],
        )],
    );
    b.node(
        "DrawTransform",
        Effect::Mutating,
        "Draws a transform's axes (X red, Y green, Z blue; rig space). Free when the host \
         asked for no debug drawing.",
        r#"DrawTransform(transform: "foot", size: 10.0),"#,
        vec![ov(
            Op::DrawTransform,
            vec![
                input("transform", T, "The transform, rig space."),
                opt("size", Value::Float(10.0), "Axis length, cm."),
                opt("thickness", Value::Float(0.5), "Width, cm."),
            ],
            vec![],
        )],
    );
    b.nodes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_overload_fits_the_operand_window() {
        // Node instructions carry inputs, outputs and state; control instructions (at most
        // six operands, `ForEachNext`) are laid out by the compiler.
        for n in registry().nodes() {
            for o in &n.overloads {
                let operands = o.inputs.len() + o.outputs.len() + o.state.len();
                assert!(
                    operands <= crate::MAX_OPERANDS,
                    "{} ({:?}) has {operands} operands, more than MAX_OPERANDS",
                    n.name,
                    o.op
                );
            }
        }
    }

    #[test]
    fn overloads_sharing_an_op_share_its_operand_layout() {
        // The executor reads an op's operands by one layout (`Op::operands`).
        for n in registry().nodes() {
            for o in &n.overloads {
                let mine = o.operands();
                assert_eq!(
                    o.op.operands().as_deref(),
                    Some(mine.as_slice()),
                    "{} ({:?})",
                    n.name,
                    o.op
                );
            }
        }
        // Control ops: jump targets are not slots.
        use crate::Access::{Read, ReadWrite, Write};
        use crate::Operand::{Slot, Target};
        assert_eq!(Op::Jump.operands().as_deref(), Some(&[Target][..]));
        assert_eq!(
            Op::JumpIfFalse.operands().as_deref(),
            Some(&[Slot(ValueType::Bool, Read), Target][..])
        );
        assert_eq!(
            Op::ForEachNext(Elem::Vec3).operands().as_deref(),
            Some(
                &[
                    Slot(ValueType::Array(Elem::Vec3), Read),
                    Slot(ValueType::Int, ReadWrite),
                    Slot(ValueType::Vec3, Write),
                    Slot(ValueType::Int, Write),
                    Slot(ValueType::Int, Write),
                    Target
                ][..]
            )
        );
    }

    #[test]
    fn names_are_unique_and_every_node_has_docs() {
        let r = registry();
        let mut seen = rustc_hash::FxHashSet::default();
        for n in r.nodes() {
            assert!(seen.insert(n.name), "duplicate node {}", n.name);
            assert!(
                !n.doc.is_empty() && !n.example.is_empty(),
                "{} lacks docs",
                n.name
            );
            assert!(!n.overloads.is_empty(), "{} has no overload", n.name);
            for o in &n.overloads {
                for p in o.inputs.iter().chain(&o.outputs) {
                    assert!(!p.doc.is_empty(), "{}.{} lacks a doc", n.name, p.name);
                    if let Some(d) = &p.default {
                        assert_eq!(
                            d.ty(),
                            p.ty,
                            "{}.{} default has the wrong type",
                            n.name,
                            p.name
                        );
                    }
                }
                let mut pins = rustc_hash::FxHashSet::default();
                for p in o.inputs.iter().chain(&o.outputs) {
                    assert!(
                        pins.insert(p.name),
                        "{} has two pins called {}",
                        n.name,
                        p.name
                    );
                }
            }
            if n.effect == Effect::Pure {
                assert!(
                    n.overloads.iter().all(|o| !o.outputs.is_empty()),
                    "pure {} has no output",
                    n.name
                );
            }
        }
    }

    #[test]
    fn overloads_of_a_node_share_pin_names() {
        // The compiler reports "unknown pin" against the first overload's pins and passes
        // over overloads by the types at the first overload's pin positions, so all
        // overloads must name their pins alike, in one order.
        for n in registry().nodes() {
            let names = |o: &Overload| o.inputs.iter().map(|p| p.name).collect::<Vec<_>>();
            let first = names(&n.overloads[0]);
            for o in &n.overloads[1..] {
                assert_eq!(names(o), first, "{}", n.name);
            }
        }
    }

    #[test]
    fn every_example_uses_its_own_node() {
        for n in registry().nodes() {
            assert!(
                n.example.contains(&format!("{}(", n.name)),
                "{}: {}",
                n.name,
                n.example
            );
        }
    }

    #[test]
    fn suggests_node_names() {
        assert_eq!(registry().suggest("Multply"), Some("Multiply"));
        assert_eq!(registry().suggest("Zzzzzzzz"), None);
    }
}
