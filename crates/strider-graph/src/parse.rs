//! From the spanned RON tree to the document types, reporting every structural problem
//! (unknown field, wrong shape) with its location.

use crate::diagnostic::{Diagnostics, FileId, Loc, SourceMap};
use crate::document::*;
use crate::reader::{Field, Span, Spanned, Value};
use crate::suggest;
use strider_nodes::ValueType;

/// Names an exec list may use that are statements, not node types.
pub(crate) const STATEMENTS: &[&str] = &[
    "Set", "Run", "Branch", "ForEach", "For", "Sequence", "Return",
];

pub(crate) struct Parser<'a> {
    pub sources: &'a SourceMap,
    pub diags: &'a mut Diagnostics,
    pub file: FileId,
}

type Fields<'v> = [Field<'v>];

/// Whether field `i`'s name is also given before it (a struct or node has a handful of
/// fields: the earlier ones are searched in place).
fn given_before(fields: &Fields<'_>, i: usize) -> bool {
    fields[..i]
        .iter()
        .any(|(earlier, _)| earlier.value == fields[i].0.value)
}

impl Parser<'_> {
    fn loc(&self, span: Span) -> Loc {
        Loc {
            file: self.file,
            span,
        }
    }

    fn err(&mut self, span: Span, message: impl Into<String>) -> crate::diagnostic::Report<'_> {
        let loc = self.loc(span);
        self.diags.error(self.sources, loc, message)
    }

    /// Fields of a struct value (named `name` if given), or an error.
    fn fields<'v>(&mut self, v: &'v Spanned<Value<'v>>, what: &str) -> Option<&'v Fields<'v>> {
        match &v.value {
            Value::Struct(_, fields) => Some(fields),
            Value::Tuple(_, []) => Some(&[]),
            Value::Unit => Some(&[]),
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected {what} `( field: value, ... )`, found {found}"),
                )
                .emit();
                None
            }
        }
    }

    /// Reports fields not in `known` (with a suggestion) and duplicates.
    fn check_fields(&mut self, fields: &Fields<'_>, known: &[&str], what: &str) {
        for (i, (name, _)) in fields.iter().enumerate() {
            if given_before(fields, i) {
                self.err(
                    name.span,
                    format!("field `{}` is given twice in {what}", name.value),
                )
                .hint("remove one of them")
                .emit();
            }
            if !known.contains(&name.value) {
                let hint = suggest(name.value, known.iter().copied())
                    .map(|s| format!("did you mean `{s}`?"))
                    .unwrap_or_else(|| format!("{what} has the fields: {}", known.join(", ")));
                self.err(
                    name.span,
                    format!("unknown field `{}` in {what}", name.value),
                )
                .hint(hint)
                .emit();
            }
        }
    }

    fn string(&mut self, v: &Spanned<Value<'_>>, what: &str) -> Option<Ident> {
        match &v.value {
            Value::String(s) => Some(Ident {
                name: s.to_string(),
                loc: self.loc(v.span),
            }),
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected {what} as a string in quotes, found {found}"),
                )
                .emit();
                None
            }
        }
    }

    fn map_entries<'v>(
        &mut self,
        v: &'v Spanned<Value<'v>>,
        what: &str,
    ) -> &'v [(Spanned<Value<'v>>, Spanned<Value<'v>>)] {
        match &v.value {
            Value::Map(entries) => entries,
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected {what} as a map `{{ \"name\": ..., }}`, found {found}"),
                )
                .emit();
                &[]
            }
        }
    }

    fn list<'v>(&mut self, v: &'v Spanned<Value<'v>>, what: &str) -> &'v [Spanned<Value<'v>>] {
        match &v.value {
            Value::List(items) => items,
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected {what} as a list `[ ... ]`, found {found}"),
                )
                .emit();
                &[]
            }
        }
    }

    fn number(&mut self, v: &Spanned<Value<'_>>, what: &str) -> Option<f64> {
        match v.value {
            Value::Int(i) => Some(i as f64),
            Value::Float(f) => Some(f),
            ref other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected {what} as a number, found {found}"),
                )
                .emit();
                None
            }
        }
    }

    fn value_type(&mut self, v: &Spanned<Value<'_>>) -> Option<ValueType> {
        let names: Vec<&str> = ValueType::ALL.iter().map(|t| t.name()).collect();
        match &v.value {
            Value::Ident(name) => match ValueType::from_name(name) {
                Some(t) => Some(t),
                None => {
                    let hint = suggest(name, names.iter().copied())
                        .map(|s| format!("did you mean `{s}`?"))
                        .unwrap_or_else(|| format!("types are: {}", names.join(", ")));
                    self.err(v.span, format!("unknown type `{name}`"))
                        .hint(hint)
                        .emit();
                    None
                }
            },
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("expected a type name such as `Float`, found {found}"),
                )
                .hint(format!("types are: {}", names.join(", ")))
                .emit();
                None
            }
        }
    }

    /// The whole graph file.
    pub fn graph(&mut self, root: &Spanned<Value<'_>>) -> Graph {
        let mut g = Graph {
            file: self.file,
            ..Graph::default()
        };
        let fields = match &root.value {
            Value::Struct(Some(name), fields) if name.value == "Graph" => fields,
            Value::Struct(Some(name), _) | Value::Tuple(Some(name), _) => {
                self.err(
                    name.span,
                    format!("a graph file starts with `Graph(`, found `{}(`", name.value),
                )
                .emit();
                return g;
            }
            other => {
                let found = other.describe();
                self.err(
                    root.span,
                    format!("a graph file holds one `Graph( ... )`, found {found}"),
                )
                .hint("start the file with `Graph(version: 1, name: \"my_graph\", ...)`")
                .emit();
                return g;
            }
        };
        const KNOWN: &[&str] = &[
            "version",
            "name",
            "conventions",
            "imports",
            "variables",
            "functions",
            "nodes",
            "events",
            "editor",
        ];
        self.check_fields(fields, KNOWN, "Graph");
        let mut version_seen = false;
        for (name, v) in fields.iter() {
            match name.value {
                "version" => {
                    version_seen = true;
                    match v.value {
                        Value::Int(n) if n >= 1 && n <= crate::FORMAT_VERSION as i64 => {
                            g.version = n as u32
                        }
                        _ => self
                            .err(v.span, "unsupported format version".to_string())
                            .hint(format!(
                                "this build reads version {}",
                                crate::FORMAT_VERSION
                            ))
                            .emit(),
                    }
                }
                "name" => {
                    g.name = self
                        .string(v, "the graph name")
                        .map(|i| i.name)
                        .unwrap_or_default()
                }
                "conventions" => self.conventions(v),
                "imports" => {
                    for item in self.list(v, "imports") {
                        if let Some(i) = self.string(item, "an import path") {
                            g.imports.push(i);
                        }
                    }
                }
                "variables" => g.variables = self.variables(v, "variables"),
                "functions" => {
                    for (k, body) in self.map_entries(v, "functions") {
                        if let Some(name) = self.string(k, "a function name")
                            && let Some(f) = self.function(name, body)
                        {
                            g.functions.push(f);
                        }
                    }
                }
                "nodes" => g.nodes = self.nodes(v),
                "events" => g.events = self.events(v),
                "editor" => g.editor = self.editor(v),
                _ => {}
            }
        }
        if !version_seen {
            self.err(root.span, "the graph has no `version:` field")
                .hint(format!(
                    "add `version: {},` after `Graph(`",
                    crate::FORMAT_VERSION
                ))
                .emit();
        }
        g
    }

    fn conventions(&mut self, v: &Spanned<Value<'_>>) {
        let Some(fields) = self.fields(v, "conventions") else {
            return;
        };
        const EXPECTED: &[(&str, &str)] = &[
            ("up", "Z"),
            ("forward", "Y"),
            ("left", "X"),
            ("units", "Centimetres"),
            ("angles", "Degrees"),
        ];
        let known: Vec<&str> = EXPECTED.iter().map(|(k, _)| *k).collect();
        self.check_fields(fields, &known, "conventions");
        for (name, value) in fields {
            if let Some((_, want)) = EXPECTED.iter().find(|(k, _)| *k == name.value) {
                let ok = matches!(&value.value, Value::Ident(s) if s == want);
                if !ok {
                    let found = value.value.describe();
                    self.err(value.span, format!("Strider rigs use `{}: {want}`, found {found}", name.value))
                        .hint("rig space is +Z up, +Y forward, +X left, centimetres and degrees; convert the graph's constants")
                        .emit();
                }
            }
        }
    }

    fn variables(&mut self, v: &Spanned<Value<'_>>, what: &str) -> Vec<VariableDecl> {
        let mut out = Vec::new();
        for (k, decl) in self.map_entries(v, what) {
            let Some(name) = self.string(k, "a variable name") else {
                continue;
            };
            let Some(fields) = self.fields(decl, "a variable") else {
                continue;
            };
            self.check_fields(fields, &["type", "default", "tunable"], "a variable");
            let mut ty = None;
            let mut ty_loc = self.loc(decl.span);
            let mut default = None;
            let mut tunable = None;
            for (f, fv) in fields {
                match f.value {
                    "type" => {
                        ty = self.value_type(fv);
                        ty_loc = self.loc(fv.span);
                    }
                    "default" => default = self.literal(fv),
                    "tunable" => tunable = self.tunable(fv),
                    _ => {}
                }
            }
            match ty {
                Some(ty) => out.push(VariableDecl {
                    name,
                    ty,
                    ty_loc,
                    default,
                    tunable,
                    loc: self.loc(decl.span),
                }),
                None if !fields.iter().any(|(f, _)| f.value == "type") => {
                    self.err(decl.span, format!("variable `{}` has no type", name.name))
                        .hint("add `type: Float` (or Int, Bool, Vec3, Quat, Transform, Bone, ...Array)")
                        .emit();
                }
                None => {}
            }
        }
        out
    }

    fn tunable(&mut self, v: &Spanned<Value<'_>>) -> Option<Tunable> {
        match &v.value {
            Value::Bool(true) => Some(Tunable::default()),
            Value::Bool(false) => None,
            _ => {
                let fields = self.fields(v, "a tunable range")?;
                self.check_fields(fields, &["min", "max"], "a tunable range");
                let mut t = Tunable::default();
                for (f, fv) in fields {
                    match f.value {
                        "min" => t.min = self.number(fv, "the minimum"),
                        "max" => t.max = self.number(fv, "the maximum"),
                        _ => {}
                    }
                }
                if let (Some(lo), Some(hi)) = (t.min, t.max)
                    && lo > hi
                {
                    self.err(
                        v.span,
                        format!("tunable range is empty: min {lo} > max {hi}"),
                    )
                    .emit();
                }
                Some(t)
            }
        }
    }

    fn params(&mut self, v: &Spanned<Value<'_>>, what: &str, allow_default: bool) -> Vec<Param> {
        let mut out = Vec::new();
        for (k, decl) in self.map_entries(v, what) {
            let Some(name) = self.string(k, "a parameter name") else {
                continue;
            };
            match &decl.value {
                Value::Ident(_) => {
                    if let Some(ty) = self.value_type(decl) {
                        out.push(Param {
                            name,
                            ty,
                            default: None,
                        });
                    }
                }
                _ => {
                    let Some(fields) =
                        self.fields(decl, "a parameter `(type: Float, default: 0.0)`")
                    else {
                        continue;
                    };
                    let known: &[&str] = if allow_default {
                        &["type", "default"]
                    } else {
                        &["type"]
                    };
                    self.check_fields(fields, known, what);
                    let mut ty = None;
                    let mut default = None;
                    for (f, fv) in fields {
                        match f.value {
                            "type" => ty = self.value_type(fv),
                            "default" if allow_default => default = self.literal(fv),
                            _ => {}
                        }
                    }
                    match ty {
                        Some(ty) => out.push(Param { name, ty, default }),
                        None if !fields.iter().any(|(f, _)| f.value == "type") => {
                            self.err(decl.span, format!("parameter `{}` has no type", name.name))
                                .emit();
                        }
                        None => {}
                    }
                }
            }
        }
        out
    }

    fn function(&mut self, name: Ident, v: &Spanned<Value<'_>>) -> Option<FunctionDecl> {
        if STATEMENTS.contains(&name.name.as_str())
            || strider_nodes::registry().get(&name.name).is_some()
        {
            self.err(
                name.loc.span,
                format!(
                    "`{}` is a built-in name and cannot name a function",
                    name.name
                ),
            )
            .hint("rename the function")
            .emit();
        }
        let fields = self.fields(v, "a function")?;
        self.check_fields(
            fields,
            &["inputs", "outputs", "locals", "nodes", "exec"],
            "a function",
        );
        let mut f = FunctionDecl {
            name,
            inputs: Vec::new(),
            outputs: Vec::new(),
            locals: Vec::new(),
            nodes: Vec::new(),
            exec: Vec::new(),
            loc: self.loc(v.span),
        };
        for (k, fv) in fields {
            match k.value {
                "inputs" => f.inputs = self.params(fv, "inputs", true),
                "outputs" => f.outputs = self.params(fv, "outputs", false),
                "locals" => f.locals = self.variables(fv, "locals"),
                "nodes" => f.nodes = self.nodes(fv),
                "exec" => f.exec = self.steps(fv),
                _ => {}
            }
        }
        Some(f)
    }

    fn nodes(&mut self, v: &Spanned<Value<'_>>) -> Vec<NodeDecl> {
        let entries = self.map_entries(v, "nodes");
        let mut out = Vec::with_capacity(entries.len());
        for (k, nv) in entries {
            let Some(id) = self.string(k, "a node id") else {
                continue;
            };
            if id.name.contains('.') || id.name.is_empty() {
                self.err(
                    id.loc.span,
                    format!("node id `{}` must be non-empty and contain no `.`", id.name),
                )
                .hint("a `.` separates a node from its output pin in links (\"node.pin\")")
                .emit();
            }
            if let Some(n) = self.node(nv, Some(id)) {
                out.push(n);
            }
        }
        out
    }

    /// `Type(pin: value, ...)`, `Type()` or `Type`; an `id:` field is allowed when
    /// `id` is `None` (inline exec nodes).
    fn node(&mut self, v: &Spanned<Value<'_>>, id: Option<Ident>) -> Option<NodeDecl> {
        let (kind, fields): (Ident, &Fields<'_>) = match &v.value {
            Value::Struct(Some(name), fields) => (
                Ident {
                    name: name.value.to_string(),
                    loc: self.loc(name.span),
                },
                fields,
            ),
            Value::Tuple(Some(name), []) => (
                Ident {
                    name: name.value.to_string(),
                    loc: self.loc(name.span),
                },
                &[],
            ),
            Value::Ident(name) => (
                Ident {
                    name: name.to_string(),
                    loc: self.loc(v.span),
                },
                &[],
            ),
            Value::Tuple(Some(name), _) => {
                self.err(
                    v.span,
                    format!(
                        "node `{}` takes named pins: `{}(pin: value, ...)`",
                        name.value, name.value
                    ),
                )
                .emit();
                return None;
            }
            other => {
                let found = other.describe();
                self.err(v.span, format!("expected a node `Type(pin: value, ...)`, found {found}"))
                    .hint("a node is written as its type followed by its input pins, e.g. `Add(a: \"x\", b: 1.0)`")
                    .emit();
                return None;
            }
        };
        let mut node = NodeDecl {
            id,
            kind,
            pins: Vec::with_capacity(fields.len()),
            loc: self.loc(v.span),
        };
        for (i, (pin, pv)) in fields.iter().enumerate() {
            if given_before(fields, i) {
                self.err(pin.span, format!("pin `{}` is given twice", pin.value))
                    .node(node.label().to_string())
                    .emit();
                continue;
            }
            if pin.value == "id" {
                if node.id.is_some() {
                    self.err(
                        pin.span,
                        "`id` is only written on exec-list nodes; in `nodes` the key is the id",
                    )
                    .node(node.label().to_string())
                    .emit();
                } else if let Some(i) = self.string(pv, "a node id") {
                    node.id = Some(i);
                }
                continue;
            }
            if let Some(value) = self.expr(pv) {
                node.pins.push(PinArg {
                    name: Ident {
                        name: pin.value.to_string(),
                        loc: self.loc(pin.span),
                    },
                    value,
                });
            }
        }
        Some(node)
    }

    /// A pin value: link, variable or literal.
    pub fn expr(&mut self, v: &Spanned<Value<'_>>) -> Option<Expr> {
        let loc = self.loc(v.span);
        match &v.value {
            Value::String(s) => {
                let (source, pin) = match s.split_once('.') {
                    Some((a, b)) => (a.to_string(), Some(b.to_string())),
                    None => (s.to_string(), None),
                };
                Some(Expr {
                    kind: ExprKind::Link { source, pin },
                    loc,
                })
            }
            Value::Tuple(Some(name), items) if name.value == "var" => match *items {
                [
                    Spanned {
                        value: Value::String(s),
                        ..
                    },
                ] => Some(Expr {
                    kind: ExprKind::Var(s.to_string()),
                    loc,
                }),
                _ => {
                    self.err(
                        v.span,
                        "`var` takes one variable name in quotes: `var(\"Name\")`",
                    )
                    .emit();
                    None
                }
            },
            _ => self.literal(v).map(|l| Expr {
                kind: ExprKind::Literal(l),
                loc,
            }),
        }
    }

    /// A constant.
    pub fn literal(&mut self, v: &Spanned<Value<'_>>) -> Option<Literal> {
        let loc = self.loc(v.span);
        let kind = match &v.value {
            Value::Bool(b) => LiteralKind::Bool(*b),
            Value::Int(i) => LiteralKind::Int(*i),
            Value::Float(f) => LiteralKind::Float(*f),
            Value::Ident(w) if *w == "None" => LiteralKind::NoBone,
            Value::Ident(w) => LiteralKind::Word(w.to_string()),
            Value::List(items) => {
                let mut out = Vec::new();
                for item in items.iter() {
                    out.push(self.literal(item)?);
                }
                LiteralKind::List(out)
            }
            Value::Tuple(None, items) => {
                let mut nums = Vec::new();
                for item in items.iter() {
                    nums.push(self.number(item, "a vector or quaternion component")?);
                }
                if nums.len() != 3 && nums.len() != 4 {
                    self.err(
                        v.span,
                        format!(
                            "a tuple of {} numbers is neither a vector (3) nor a quaternion (4)",
                            nums.len()
                        ),
                    )
                    .emit();
                    return None;
                }
                LiteralKind::Numbers(nums)
            }
            Value::Tuple(Some(name), items) => match (name.value, *items) {
                (
                    "bone",
                    [
                        Spanned {
                            value: Value::String(s),
                            ..
                        },
                    ],
                ) => LiteralKind::Bone(s.to_string()),
                (
                    "name",
                    [
                        Spanned {
                            value: Value::String(s),
                            ..
                        },
                    ],
                ) => LiteralKind::Name(s.to_string()),
                ("euler", [x, y, z]) => {
                    let x = self.number(x, "an angle")?;
                    let y = self.number(y, "an angle")?;
                    let z = self.number(z, "an angle")?;
                    LiteralKind::Euler([x, y, z])
                }
                ("bone" | "name", _) => {
                    self.err(
                        v.span,
                        format!(
                            "`{}` takes one text in quotes: `{}(\"...\")`",
                            name.value, name.value
                        ),
                    )
                    .emit();
                    return None;
                }
                ("euler", _) => {
                    self.err(
                        v.span,
                        "`euler` takes three angles in degrees: `euler(x, y, z)`",
                    )
                    .emit();
                    return None;
                }
                (other, _) => {
                    self.err(name.span, format!("unknown value constructor `{other}(...)`"))
                        .hint("values are numbers, (x, y, z), (x, y, z, w), euler(x, y, z), bone(\"name\"), name(\"text\"), var(\"Name\"), [..] or (translation: .., rotation: .., scale: ..)")
                        .emit();
                    return None;
                }
            },
            Value::Struct(name, fields) => {
                if let Some(n) = name
                    && n.value != "Transform"
                {
                    self.err(
                        n.span,
                        format!(
                            "`{}(...)` is a node; a node cannot be written inside a pin",
                            n.value
                        ),
                    )
                    .hint("give it an id in `nodes` and link to it by that id")
                    .emit();
                    return None;
                }
                self.check_fields(fields, &["translation", "rotation", "scale"], "a transform");
                let mut t = (None, None, None);
                for (f, fv) in fields.iter() {
                    let lit = self.literal(fv).map(Box::new);
                    match f.value {
                        "translation" => t.0 = lit,
                        "rotation" => t.1 = lit,
                        "scale" => t.2 = lit,
                        _ => {}
                    }
                }
                LiteralKind::Transform {
                    translation: t.0,
                    rotation: t.1,
                    scale: t.2,
                }
            }
            other => {
                let found = other.describe();
                self.err(
                    v.span,
                    format!("{found} is not a value Strider understands"),
                )
                .hint("links are written as \"node\" or \"node.pin\" in double quotes")
                .emit();
                return None;
            }
        };
        Some(Literal { kind, loc })
    }

    fn steps(&mut self, v: &Spanned<Value<'_>>) -> Vec<Step> {
        let mut out = Vec::new();
        for item in self.list(v, "an exec list") {
            if let Some(s) = self.step(item) {
                out.push(s);
            }
        }
        out
    }

    fn step(&mut self, v: &Spanned<Value<'_>>) -> Option<Step> {
        let loc = self.loc(v.span);
        let name = match &v.value {
            Value::Struct(Some(n), _) | Value::Tuple(Some(n), _) => n.value,
            Value::Ident(n) => *n,
            other => {
                let found = other.describe();
                self.err(v.span, format!("expected an exec step such as `Set(\"Var\", \"node\")` or `SetTransform(...)`, found {found}"))
                    .emit();
                return None;
            }
        };
        match (name, &v.value) {
            ("Set", Value::Tuple(_, items)) => match *items {
                [var, value] => {
                    let var = self.string(var, "the variable name")?;
                    let value = self.expr(value)?;
                    Some(Step::Set { var, value, loc })
                }
                _ => {
                    self.err(
                        v.span,
                        "`Set` takes a variable name and a value: `Set(\"Var\", value)`",
                    )
                    .emit();
                    None
                }
            },
            ("Run", Value::Tuple(_, items)) => match *items {
                [id] => self.string(id, "the node id").map(Step::Run),
                _ => {
                    self.err(v.span, "`Run` takes one node id: `Run(\"node\")`")
                        .emit();
                    None
                }
            },
            ("Sequence", Value::Tuple(_, items)) => {
                let blocks = items.iter().map(|b| self.steps(b)).collect();
                Some(Step::Sequence(blocks, loc))
            }
            ("Return", Value::Ident(_)) | ("Return", Value::Tuple(_, _)) => Some(Step::Return {
                values: Vec::new(),
                loc,
            }),
            ("Return", Value::Struct(_, fields)) => {
                let mut values = Vec::new();
                for (f, fv) in fields.iter() {
                    if let Some(value) = self.expr(fv) {
                        values.push(PinArg {
                            name: Ident {
                                name: f.value.to_string(),
                                loc: self.loc(f.span),
                            },
                            value,
                        });
                    }
                }
                Some(Step::Return { values, loc })
            }
            ("Branch", Value::Struct(_, fields)) => {
                self.check_fields(fields, &["condition", "then", "else"], "Branch");
                let mut condition = None;
                let (mut then, mut otherwise) = (Vec::new(), Vec::new());
                for (f, fv) in fields.iter() {
                    match f.value {
                        "condition" => condition = self.expr(fv),
                        "then" => then = self.steps(fv),
                        "else" => otherwise = self.steps(fv),
                        _ => {}
                    }
                }
                let Some(condition) = condition else {
                    self.err(v.span, "`Branch` needs a `condition:`").emit();
                    return None;
                };
                Some(Step::Branch {
                    condition,
                    then,
                    otherwise,
                    loc,
                })
            }
            ("ForEach", Value::Struct(_, fields)) => {
                self.check_fields(
                    fields,
                    &["items", "element", "index", "count", "body"],
                    "ForEach",
                );
                let (mut items, mut element, mut index, mut count, mut body) =
                    (None, None, None, None, Vec::new());
                for (f, fv) in fields.iter() {
                    match f.value {
                        "items" => items = self.expr(fv),
                        "element" => element = self.string(fv, "the element's name"),
                        "index" => index = self.string(fv, "the index's name"),
                        "count" => count = self.string(fv, "the count's name"),
                        "body" => body = self.steps(fv),
                        _ => {}
                    }
                }
                let (Some(items), Some(element)) = (items, element) else {
                    self.err(v.span, "`ForEach` needs `items:` (an array) and `element:` (a name for the current item)")
                        .hint("ForEach(items: var(\"FootArray\"), element: \"foot\", index: \"i\", body: [ ... ])")
                        .emit();
                    return None;
                };
                Some(Step::ForEach {
                    items,
                    element,
                    index,
                    count,
                    body,
                    loc,
                })
            }
            ("For", Value::Struct(_, fields)) => {
                self.check_fields(fields, &["count", "index", "body"], "For");
                let (mut count, mut index, mut body) = (None, None, Vec::new());
                for (f, fv) in fields.iter() {
                    match f.value {
                        "count" => count = self.expr(fv),
                        "index" => index = self.string(fv, "the index's name"),
                        "body" => body = self.steps(fv),
                        _ => {}
                    }
                }
                let (Some(count), Some(index)) = (count, index) else {
                    self.err(v.span, "`For` needs `count:` and `index:`")
                        .hint("For(count: 3, index: \"i\", body: [ ... ])")
                        .emit();
                    return None;
                };
                Some(Step::For {
                    count,
                    index,
                    body,
                    loc,
                })
            }
            (s, _) if STATEMENTS.contains(&s) => {
                self.err(v.span, format!("malformed `{s}` step"))
                    .hint(match s {
                        "Set" => "Set(\"Var\", value)",
                        "Run" => "Run(\"node_id\")",
                        "Branch" => "Branch(condition: \"c\", then: [..], else: [..])",
                        "ForEach" => "ForEach(items: var(\"Array\"), element: \"e\", index: \"i\", body: [..])",
                        "For" => "For(count: 3, index: \"i\", body: [..])",
                        "Sequence" => "Sequence([..], [..])",
                        _ => "Return or Return(output: value)",
                    })
                    .emit();
                None
            }
            _ => self.node(v, None).map(Step::Node),
        }
    }

    fn events(&mut self, v: &Spanned<Value<'_>>) -> Vec<EventDecl> {
        let entries: Vec<(Spanned<&str>, &Spanned<Value<'_>>)> = match &v.value {
            Value::Map(entries) => entries
                .iter()
                .filter_map(|(k, v)| {
                    let name: &str = match &k.value {
                        Value::Ident(s) => s,
                        Value::String(s) => s,
                        _ => return None,
                    };
                    let name = Spanned {
                        value: name,
                        span: k.span,
                    };
                    Some((name, v))
                })
                .collect(),
            Value::Struct(None, fields) => fields.iter().map(|(k, v)| (*k, v)).collect(),
            other => {
                let found = other.describe();
                self.err(v.span, format!("expected events as `{{ construction: [..], forward: [..] }}`, found {found}"))
                    .emit();
                return Vec::new();
            }
        };
        let mut out: Vec<EventDecl> = Vec::new();
        for (k, body) in entries {
            let kind = match k.value {
                "construction" => EventKind::Construction,
                "forward" => EventKind::Forward,
                other => {
                    let hint = suggest(other, ["construction", "forward"])
                        .map(|s| format!("did you mean `{s}`?"))
                        .unwrap_or_else(|| "events are `construction` and `forward`".into());
                    self.err(k.span, format!("unknown event `{other}`"))
                        .hint(hint)
                        .emit();
                    continue;
                }
            };
            if out.iter().any(|e| e.kind == kind) {
                self.err(k.span, format!("event `{}` is defined twice", k.value))
                    .emit();
                continue;
            }
            let steps = self.steps(body);
            out.push(EventDecl {
                kind,
                steps,
                loc: self.loc(k.span),
            });
        }
        out
    }

    fn editor(&mut self, v: &Spanned<Value<'_>>) -> Editor {
        let mut e = Editor::default();
        let Some(fields) = self.fields(v, "the editor section") else {
            return e;
        };
        self.check_fields(fields, &["positions", "comments"], "the editor section");
        for (f, fv) in fields {
            match f.value {
                "positions" => {
                    for (k, pv) in self.map_entries(fv, "positions") {
                        let Some(id) = self.string(k, "a node id") else {
                            continue;
                        };
                        match &pv.value {
                            Value::Tuple(None, xy) if xy.len() == 2 => {
                                if let (Some(x), Some(y)) =
                                    (self.number(&xy[0], "x"), self.number(&xy[1], "y"))
                                {
                                    e.positions.push((id, [x, y]));
                                }
                            }
                            _ => self.err(pv.span, "a position is `(x, y)`").emit(),
                        }
                    }
                }
                "comments" => {
                    for c in self.list(fv, "comments") {
                        let Some(cf) = self.fields(c, "a comment box") else {
                            continue;
                        };
                        self.check_fields(cf, &["title", "color", "nodes"], "a comment box");
                        let mut comment = Comment {
                            title: String::new(),
                            color: [0.3, 0.3, 0.3],
                            nodes: Vec::new(),
                        };
                        for (k, kv) in cf {
                            match k.value {
                                "title" => {
                                    comment.title = self
                                        .string(kv, "the title")
                                        .map(|i| i.name)
                                        .unwrap_or_default()
                                }
                                "color" => match &kv.value {
                                    Value::Tuple(None, rgb) if rgb.len() == 3 => {
                                        for (i, c) in rgb.iter().enumerate() {
                                            comment.color[i] =
                                                self.number(c, "a colour channel").unwrap_or(0.0);
                                        }
                                    }
                                    _ => self
                                        .err(kv.span, "a colour is `(r, g, b)`, each 0..1")
                                        .emit(),
                                },
                                "nodes" => {
                                    for n in self.list(kv, "the boxed nodes") {
                                        if let Some(i) = self.string(n, "a node id") {
                                            comment.nodes.push(i);
                                        }
                                    }
                                }
                                _ => {}
                            }
                        }
                        e.comments.push(comment);
                    }
                }
                _ => {}
            }
        }
        e
    }
}
