//! The checker: resolves names and types, picks overloads, and validates exec lists.
//! Produces a [`Checked`] graph in which every reference is an index and every type is
//! known, or the list of every problem found.

use crate::literal::{self, Fit};
use fixedbitset::FixedBitSet;
use petgraph::algo::{kosaraju_scc, toposort};
use petgraph::graph::{DiGraph, NodeIndex};
use rustc_hash::{FxHashMap, FxHashSet};
use smallvec::SmallVec;
use std::borrow::Cow;
use strider_graph::diagnostic::{Diagnostics, Loc, SourceMap};
use strider_graph::{
    Diagnostic, EventKind, Expr, ExprKind, FunctionDecl, Graph, Ident, LoadedGraph, NodeDecl,
    PinArg, Step, suggest,
};
use strider_nodes::{Effect, Op, PinSpec, Value, ValueType, registry};

/// Why a node's given pins do not fit an overload (formatted only when reported: overload
/// resolution tries and rejects many).
enum Mismatch {
    /// A link of another type.
    Types {
        expected: ValueType,
        found: ValueType,
    },
    /// A literal that does not convert, and why.
    Literal(String),
    /// A link whose source failed to resolve (already reported).
    Unresolved,
}

impl std::fmt::Display for Mismatch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Mismatch::Types { expected, found } => write!(f, "expected {expected}, found {found}"),
            Mismatch::Literal(m) => f.write_str(m),
            Mismatch::Unresolved => Ok(()),
        }
    }
}

/// Where a value comes from.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Src {
    Node {
        node: usize,
        out: usize,
    },
    Input(usize),
    Local(usize),
    Global(usize),
    Loop {
        lp: usize,
        part: LoopPart,
    },
    /// A literal (`loc`: where it is written; `None` for a pin's default).
    Const {
        value: Value,
        loc: Option<Loc>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LoopPart {
    Element,
    Index,
    Count,
}

/// An input of a node or step: its source, and whether the Int → Float conversion applies.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Arg {
    pub src: Src,
    pub ty: ValueType,
    pub to_float: bool,
}

impl Arg {
    /// A constant of type `ty` (`loc`: the literal it was written as; `None` for a default).
    fn constant(value: Value, ty: ValueType, loc: Option<Loc>) -> Self {
        Arg {
            src: Src::Const { value, loc },
            ty,
            to_float: false,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NodeKind {
    Builtin(Op),
    Call(usize),
}

#[derive(Clone, Debug)]
pub(crate) struct CNode {
    pub kind: NodeKind,
    pub pure: bool,
    pub inputs: Vec<Arg>,
    pub outputs: Vec<ValueType>,
    /// Hidden persistent state slots of a stateful built-in node.
    pub state: Vec<ValueType>,
}

#[derive(Clone, Debug)]
pub(crate) struct CLoop {
    pub element: ValueType,
    /// A counted `For` loop (else a `ForEach`).
    pub is_for: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum VarRef {
    Global(usize),
    Local(usize),
}

#[derive(Clone, Debug)]
pub(crate) enum CStep {
    Set {
        target: VarRef,
        ty: ValueType,
        arg: Arg,
    },
    Exec(usize),
    Branch {
        condition: Arg,
        then: Vec<CStep>,
        otherwise: Vec<CStep>,
    },
    ForEach {
        items: Arg,
        lp: usize,
        body: Vec<CStep>,
    },
    For {
        count: Arg,
        lp: usize,
        body: Vec<CStep>,
    },
    Sequence(Vec<Vec<CStep>>),
    Return(Vec<(usize, Arg)>),
}

/// A checked function body or the graph's top level.
#[derive(Clone, Debug, Default)]
pub(crate) struct Body {
    pub nodes: Vec<CNode>,
    pub loops: Vec<CLoop>,
    pub inputs: Vec<ValueType>,
    pub outputs: Vec<ValueType>,
    /// Local variables: type and default.
    pub locals: Vec<(ValueType, Value, String)>,
    pub exec: Vec<CStep>,
    pub construction: Vec<CStep>,
    pub forward: Vec<CStep>,
}

#[derive(Clone, Debug)]
pub(crate) struct GlobalVar {
    pub name: String,
    pub ty: ValueType,
    pub default: Value,
    pub tunable: Option<(Option<f32>, Option<f32>)>,
    pub location: String,
}

#[derive(Debug)]
pub(crate) struct Checked {
    pub globals: Vec<GlobalVar>,
    pub functions: Vec<Body>,
    pub graph: Body,
}

struct FnSig<'a> {
    decl: &'a FunctionDecl,
    pure: bool,
}

pub(crate) fn check(loaded: &LoadedGraph) -> Result<Checked, Vec<Diagnostic>> {
    let mut diags = Diagnostics::default();
    let sources = &loaded.sources;
    let files: Vec<&Graph> = std::iter::once(&loaded.main)
        .chain(&loaded.libraries)
        .collect();

    // Variables of every file share one namespace.
    let mut globals: Vec<GlobalVar> = Vec::new();
    let mut global_index: FxHashMap<String, usize> = FxHashMap::default();
    for g in &files {
        for v in &g.variables {
            if let Some(&prev) = global_index.get(&v.name.name) {
                diags
                    .error(
                        sources,
                        v.name.loc,
                        format!("variable `{}` is declared twice", v.name.name),
                    )
                    .hint(format!(
                        "the first declaration is at {}",
                        globals[prev].location
                    ))
                    .emit();
                continue;
            }
            let default = match &v.default {
                None => v.ty.zero(),
                Some(lit) => match literal::convert(lit, v.ty, &[]) {
                    Ok((val, _)) => val,
                    Err(m) => {
                        diags
                            .error(
                                sources,
                                lit.loc,
                                format!("default of variable `{}`: {m}", v.name.name),
                            )
                            .emit();
                        v.ty.zero()
                    }
                },
            };
            if v.ty == ValueType::Name {
                diags
                    .error(sources, v.ty_loc, format!("variable `{}` cannot be a Name", v.name.name))
                    .hint("Name is a constant text written in a pin, e.g. name(\"foot\"); variables hold values that change")
                    .emit();
            }
            let tunable = v
                .tunable
                .map(|t| (t.min.map(|x| x as f32), t.max.map(|x| x as f32)));
            if tunable.is_some()
                && !matches!(
                    v.ty,
                    ValueType::Float | ValueType::Int | ValueType::Bool | ValueType::Vec3
                )
            {
                diags
                    .error(sources, v.ty_loc, format!("tunable variable `{}` is {}, but only Float, Int, Bool and Vec3 can be tuned", v.name.name, v.ty))
                    .emit();
            }
            global_index.insert(v.name.name.clone(), globals.len());
            globals.push(GlobalVar {
                name: v.name.name.clone(),
                ty: v.ty,
                default,
                tunable,
                location: sources.describe(v.name.loc),
            });
        }
    }

    // Functions of every file share one namespace.
    let mut fn_decls: Vec<&FunctionDecl> = Vec::new();
    let mut fn_index: FxHashMap<String, usize> = FxHashMap::default();
    for g in &files {
        for f in &g.functions {
            if let Some(&prev) = fn_index.get(&f.name.name) {
                diags
                    .error(
                        sources,
                        f.name.loc,
                        format!("function `{}` is defined twice", f.name.name),
                    )
                    .hint(format!(
                        "the first definition is at {}",
                        sources.describe(fn_decls[prev].name.loc)
                    ))
                    .emit();
                continue;
            }
            fn_index.insert(f.name.name.clone(), fn_decls.len());
            fn_decls.push(f);
        }
    }

    // Recursion: a call graph between functions.
    let mut calls: DiGraph<usize, ()> = DiGraph::new();
    let vertices: Vec<NodeIndex> = (0..fn_decls.len()).map(|i| calls.add_node(i)).collect();
    for (i, f) in fn_decls.iter().enumerate() {
        let mut callees = Vec::new();
        collect_calls(&f.nodes, &f.exec, &fn_index, &mut callees);
        for c in callees {
            calls.update_edge(vertices[i], vertices[c], ());
        }
    }
    let mut recursive = vec![false; fn_decls.len()];
    for scc in kosaraju_scc(&calls) {
        let self_loop = scc.len() == 1 && calls.contains_edge(scc[0], scc[0]);
        if scc.len() > 1 || self_loop {
            for v in &scc {
                recursive[calls[*v]] = true;
            }
            let cycle: Vec<usize> = cycle_path(&calls, &scc).iter().map(|v| calls[*v]).collect();
            let path = format_path(cycle.iter().map(|&n| fn_decls[n].name.name.clone()));
            let first = fn_decls[cycle[0]];
            diags
                .error(sources, first.name.loc, format!("recursion: {path}"))
                .hint("function calls are inlined; a function may not call itself, directly or through others — use a For or ForEach loop")
                .emit();
        }
    }

    // Purity, bottom-up over the (acyclic part of the) call graph.
    let mut purity: Vec<Option<bool>> = vec![None; fn_decls.len()];
    for i in 0..fn_decls.len() {
        function_purity(i, &fn_decls, &fn_index, &recursive, &mut purity);
    }
    let sigs: Vec<FnSig<'_>> = fn_decls
        .iter()
        .enumerate()
        .map(|(i, d)| FnSig {
            decl: d,
            pure: purity[i].unwrap_or(false),
        })
        .collect();

    let ctx = Ctx {
        sources,
        globals: &globals,
        global_index: &global_index,
        fns: &sigs,
        fn_index: &fn_index,
    };
    let mut functions = Vec::new();
    for (i, f) in fn_decls.iter().enumerate() {
        if recursive[i] {
            functions.push(Body::default());
            continue;
        }
        let mut sc = Scope::new(&ctx, Some(f));
        let body = sc.check_body(&f.nodes, &[&f.exec], &mut diags);
        functions.push(body);
    }
    let main = &loaded.main;
    // Each event's steps, one after another; borrowed where the graph has one such event
    // (as it usually does), else the events' steps joined.
    let event_steps = |kind: EventKind| -> Cow<'_, [Step]> {
        let mut events = main.events.iter().filter(|e| e.kind == kind);
        match (events.next(), events.next()) {
            (None, _) => Cow::Borrowed(&[]),
            (Some(only), None) => Cow::Borrowed(&only.steps),
            _ => Cow::Owned(
                main.events
                    .iter()
                    .filter(|e| e.kind == kind)
                    .flat_map(|e| e.steps.iter().cloned())
                    .collect(),
            ),
        }
    };
    let (construction, forward) = (
        event_steps(EventKind::Construction),
        event_steps(EventKind::Forward),
    );
    let mut sc = Scope::new(&ctx, None);
    let mut graph = sc.check_body(&main.nodes, &[&*construction, &*forward], &mut diags);
    let mut lists = std::mem::take(&mut graph.exec_lists());
    graph.forward = lists.pop().unwrap_or_default();
    graph.construction = lists.pop().unwrap_or_default();

    if diags.is_empty() {
        Ok(Checked {
            globals,
            functions,
            graph,
        })
    } else {
        Err(in_source_order(diags.into_vec()))
    }
}

/// Diagnostics sorted by file (in the order files were first reported), line and column.
fn in_source_order(mut list: Vec<Diagnostic>) -> Vec<Diagnostic> {
    let mut files: Vec<std::path::PathBuf> = Vec::new();
    for d in &list {
        if !files.contains(&d.path) {
            files.push(d.path.clone());
        }
    }
    list.sort_by_key(|d| (files.iter().position(|f| *f == d.path), d.line, d.col));
    list
}

impl Body {
    /// The checked exec lists, in the order given to `check_body`, stored in `exec` as a
    /// sequence of blocks.
    fn exec_lists(&mut self) -> Vec<Vec<CStep>> {
        match std::mem::take(&mut self.exec).pop() {
            Some(CStep::Sequence(blocks)) => blocks,
            _ => Vec::new(),
        }
    }
}

fn collect_calls(
    nodes: &[NodeDecl],
    steps: &[Step],
    fn_index: &FxHashMap<String, usize>,
    out: &mut Vec<usize>,
) {
    for n in nodes {
        if let Some(&f) = fn_index.get(&n.kind.name) {
            out.push(f);
        }
    }
    for_each_node_in_steps(steps, &mut |n| {
        if let Some(&f) = fn_index.get(&n.kind.name) {
            out.push(f);
        }
    });
}

fn for_each_node_in_steps<'a>(steps: &'a [Step], f: &mut dyn FnMut(&'a NodeDecl)) {
    for s in steps {
        match s {
            Step::Node(n) => f(n),
            Step::Branch {
                then, otherwise, ..
            } => {
                for_each_node_in_steps(then, f);
                for_each_node_in_steps(otherwise, f);
            }
            Step::ForEach { body, .. } | Step::For { body, .. } => for_each_node_in_steps(body, f),
            Step::Sequence(blocks, _) => {
                for b in blocks {
                    for_each_node_in_steps(b, f);
                }
            }
            Step::Set { .. } | Step::Run(_) | Step::Return { .. } => {}
        }
    }
}

/// A function is pure when its body writes no graph variable, runs no mutating node and
/// calls only pure functions.
fn function_purity(
    i: usize,
    decls: &[&FunctionDecl],
    index: &FxHashMap<String, usize>,
    recursive: &[bool],
    memo: &mut Vec<Option<bool>>,
) -> bool {
    if let Some(p) = memo[i] {
        return p;
    }
    if recursive[i] {
        memo[i] = Some(false);
        return false;
    }
    let f = decls[i];
    let locals: Vec<&str> = f.locals.iter().map(|l| l.name.name.as_str()).collect();
    let mut pure = true;
    let check_node = |n: &NodeDecl, memo: &mut Vec<Option<bool>>| {
        if let Some(spec) = registry().get(&n.kind.name) {
            spec.effect == Effect::Pure
        } else if let Some(&c) = index.get(&n.kind.name) {
            function_purity(c, decls, index, recursive, memo)
        } else {
            true
        }
    };
    let mut exec_nodes = Vec::new();
    for_each_node_in_steps(&f.exec, &mut |n| exec_nodes.push(n));
    for n in f.nodes.iter().chain(exec_nodes) {
        if !check_node(n, memo) {
            pure = false;
        }
    }
    fn sets_global(steps: &[Step], locals: &[&str]) -> bool {
        steps.iter().any(|s| match s {
            Step::Set { var, .. } => !locals.contains(&var.name.as_str()),
            Step::Branch {
                then, otherwise, ..
            } => sets_global(then, locals) || sets_global(otherwise, locals),
            Step::ForEach { body, .. } | Step::For { body, .. } => sets_global(body, locals),
            Step::Sequence(blocks, _) => blocks.iter().any(|b| sets_global(b, locals)),
            _ => false,
        })
    }
    if sets_global(&f.exec, &locals) {
        pure = false;
    }
    memo[i] = Some(pure);
    pure
}

struct Ctx<'a> {
    sources: &'a SourceMap,
    globals: &'a [GlobalVar],
    global_index: &'a FxHashMap<String, usize>,
    fns: &'a [FnSig<'a>],
    fn_index: &'a FxHashMap<String, usize>,
}

#[derive(Clone, Copy, Debug)]
enum Name {
    Node(usize),
    Input(usize),
    Loop(usize, LoopPart),
}

/// One node of the scope being checked, before and after resolution.
struct Slot<'a> {
    decl: &'a NodeDecl,
    /// Declared in `nodes` (and so must be `Run` if mutating) rather than inline.
    declared: bool,
    resolved: Option<CNode>,
    failed: bool,
    ran: bool,
}

struct LoopDecl<'a> {
    items: &'a Expr,
    is_for: bool,
    element: Option<ValueType>,
    names: Vec<&'a Ident>,
}

struct Scope<'a, 'c> {
    ctx: &'c Ctx<'a>,
    function: Option<&'a FunctionDecl>,
    nodes: Vec<Slot<'a>>,
    loops: Vec<LoopDecl<'a>>,
    names: FxHashMap<&'a str, Name>,
    locals: FxHashMap<String, usize>,
    /// Inline exec nodes, in walk order, so the step walk can find its node index.
    inline_index: FxHashMap<*const NodeDecl, usize>,
    loop_index: FxHashMap<*const Step, usize>,
}

impl<'a, 'c> Scope<'a, 'c> {
    fn new(ctx: &'c Ctx<'a>, function: Option<&'a FunctionDecl>) -> Self {
        Self {
            ctx,
            function,
            nodes: Vec::new(),
            loops: Vec::new(),
            names: FxHashMap::default(),
            locals: FxHashMap::default(),
            inline_index: FxHashMap::default(),
            loop_index: FxHashMap::default(),
        }
    }

    fn sources(&self) -> &'a SourceMap {
        self.ctx.sources
    }

    fn declare(&mut self, ident: &'a Ident, name: Name, diags: &mut Diagnostics) {
        if self.names.contains_key(ident.name.as_str()) {
            diags
                .error(self.sources(), ident.loc, format!("duplicate id `{}`: another node, input or loop name in this scope already uses it", ident.name))
                .node(ident.name.clone())
                .hint("ids must be unique within a graph's top level and within each function")
                .emit();
        } else {
            self.names.insert(&ident.name, name);
        }
    }

    fn collect_steps(&mut self, steps: &'a [Step], diags: &mut Diagnostics) {
        for s in steps {
            match s {
                Step::Node(n) => {
                    let idx = self.nodes.len();
                    self.nodes.push(Slot {
                        decl: n,
                        declared: false,
                        resolved: None,
                        failed: false,
                        ran: true,
                    });
                    self.inline_index.insert(n as *const _, idx);
                    if let Some(id) = &n.id {
                        self.declare(id, Name::Node(idx), diags);
                    }
                }
                Step::ForEach {
                    items,
                    element,
                    index,
                    count,
                    body,
                    ..
                } => {
                    let lp = self.loops.len();
                    let mut names = vec![element];
                    self.declare(element, Name::Loop(lp, LoopPart::Element), diags);
                    if let Some(i) = index {
                        self.declare(i, Name::Loop(lp, LoopPart::Index), diags);
                        names.push(i);
                    }
                    if let Some(c) = count {
                        self.declare(c, Name::Loop(lp, LoopPart::Count), diags);
                        names.push(c);
                    }
                    self.loops.push(LoopDecl {
                        items,
                        is_for: false,
                        element: None,
                        names,
                    });
                    self.loop_index.insert(s as *const _, lp);
                    self.collect_steps(body, diags);
                }
                Step::For {
                    count, index, body, ..
                } => {
                    let lp = self.loops.len();
                    self.declare(index, Name::Loop(lp, LoopPart::Index), diags);
                    self.loops.push(LoopDecl {
                        items: count,
                        is_for: true,
                        element: Some(ValueType::Int),
                        names: vec![index],
                    });
                    self.loop_index.insert(s as *const _, lp);
                    self.collect_steps(body, diags);
                }
                Step::Branch {
                    then, otherwise, ..
                } => {
                    self.collect_steps(then, diags);
                    self.collect_steps(otherwise, diags);
                }
                Step::Sequence(blocks, _) => {
                    for b in blocks {
                        self.collect_steps(b, diags);
                    }
                }
                Step::Set { .. } | Step::Run(_) | Step::Return { .. } => {}
            }
        }
    }

    fn check_body(
        &mut self,
        nodes: &'a [NodeDecl],
        lists: &[&'a [Step]],
        diags: &mut Diagnostics,
    ) -> Body {
        let mut body = Body::default();
        // Room for a name per node and input (ids and inputs; loop names may add more).
        self.names
            .reserve(nodes.len() + self.function.map_or(0, |f| f.inputs.len()));
        if let Some(f) = self.function {
            for (i, p) in f.inputs.iter().enumerate() {
                self.declare(&p.name, Name::Input(i), diags);
                body.inputs.push(p.ty);
            }
            let mut seen_out: Vec<&str> = Vec::new();
            for p in &f.outputs {
                if seen_out.contains(&p.name.name.as_str()) {
                    diags
                        .error(
                            self.sources(),
                            p.name.loc,
                            format!("output `{}` is declared twice", p.name.name),
                        )
                        .emit();
                }
                seen_out.push(&p.name.name);
                body.outputs.push(p.ty);
            }
            for l in &f.locals {
                if self.ctx.global_index.contains_key(&l.name.name) {
                    diags
                        .error(
                            self.sources(),
                            l.name.loc,
                            format!(
                                "local variable `{}` has the name of a graph variable",
                                l.name.name
                            ),
                        )
                        .hint("rename the local; var(\"...\") must name one variable unambiguously")
                        .emit();
                }
                if self.locals.contains_key(&l.name.name) {
                    diags
                        .error(
                            self.sources(),
                            l.name.loc,
                            format!("local variable `{}` is declared twice", l.name.name),
                        )
                        .emit();
                    continue;
                }
                let default = match &l.default {
                    None => l.ty.zero(),
                    Some(lit) => match literal::convert(lit, l.ty, &[]) {
                        Ok((v, _)) => v,
                        Err(m) => {
                            diags
                                .error(
                                    self.sources(),
                                    lit.loc,
                                    format!("default of local `{}`: {m}", l.name.name),
                                )
                                .emit();
                            l.ty.zero()
                        }
                    },
                };
                self.locals.insert(l.name.name.clone(), body.locals.len());
                body.locals
                    .push((l.ty, default, self.sources().describe(l.name.loc)));
            }
        }
        for n in nodes {
            let idx = self.nodes.len();
            self.nodes.push(Slot {
                decl: n,
                declared: true,
                resolved: None,
                failed: false,
                ran: false,
            });
            if let Some(id) = &n.id {
                self.declare(id, Name::Node(idx), diags);
            }
        }
        for list in lists {
            self.collect_steps(list, diags);
        }

        self.resolve_all(diags);

        let mut blocks = Vec::new();
        for list in lists {
            let mut active = Vec::new();
            blocks.push(self.steps(list, &mut active, diags));
        }
        for slot in &self.nodes {
            if slot.declared
                && !slot.ran
                && let Some(n) = &slot.resolved
                && !n.pure
            {
                let what = if matches!(n.kind, NodeKind::Call(_)) {
                    "calls a function that changes state"
                } else {
                    "changes state"
                };
                diags
                    .error(
                        self.sources(),
                        slot.decl.loc,
                        format!(
                            "node `{}` ({}) {what} but is not reachable from any event",
                            slot.decl.label(),
                            slot.decl.kind.name
                        ),
                    )
                    .node(slot.decl.label().to_string())
                    .hint(format!(
                        "add `Run(\"{}\")` to an exec list, or write the node inline in one",
                        slot.decl.label()
                    ))
                    .emit();
            }
        }
        body.nodes = self
            .nodes
            .iter()
            .map(|s| {
                s.resolved.clone().unwrap_or(CNode {
                    kind: NodeKind::Builtin(Op::End),
                    pure: true,
                    inputs: Vec::new(),
                    outputs: Vec::new(),
                    state: Vec::new(),
                })
            })
            .collect();
        body.loops = self
            .loops
            .iter()
            .map(|l| CLoop {
                element: l.element.unwrap_or(ValueType::Int),
                is_for: l.is_for,
            })
            .collect();
        if self.function.is_some() {
            body.exec = blocks.pop().unwrap_or_default();
        } else {
            body.exec = vec![CStep::Sequence(blocks)];
        }
        body
    }

    /// Resolves every node and loop in data-dependency order; reports cycles.
    fn resolve_all(&mut self, diags: &mut Diagnostics) {
        let n = self.nodes.len();
        let mut g: DiGraph<usize, ()> = DiGraph::new();
        let v: Vec<NodeIndex> = (0..n + self.loops.len()).map(|i| g.add_node(i)).collect();
        let link_deps = |e: &Expr, names: &FxHashMap<&'a str, Name>| -> Option<usize> {
            if let ExprKind::Link { source, .. } = &e.kind {
                match names.get(source.as_str()) {
                    Some(Name::Node(j)) => return Some(*j),
                    Some(Name::Loop(lp, _)) => return Some(n + lp),
                    _ => {}
                }
            }
            None
        };
        for (i, slot) in self.nodes.iter().enumerate() {
            for p in &slot.decl.pins {
                if let Some(d) = link_deps(&p.value, &self.names) {
                    g.update_edge(v[d], v[i], ());
                }
            }
        }
        for (lp, l) in self.loops.iter().enumerate() {
            if let Some(d) = link_deps(l.items, &self.names) {
                g.update_edge(v[d], v[n + lp], ());
            }
        }
        // One pass orders an acyclic body (the usual case); the cycles are only looked for
        // when it fails.
        if let Ok(order) = toposort(&g, None) {
            for x in order {
                self.resolve_one(g[x], diags);
            }
            return;
        }
        let mut in_cycle = vec![false; n + self.loops.len()];
        for scc in kosaraju_scc(&g) {
            let self_loop = scc.len() == 1 && g.contains_edge(scc[0], scc[0]);
            if scc.len() > 1 || self_loop {
                for x in &scc {
                    in_cycle[g[*x]] = true;
                }
                let members: Vec<usize> = cycle_path(&g, &scc).iter().map(|x| g[*x]).collect();
                let label = |m: usize| -> String {
                    if m < n {
                        self.nodes[m].decl.label().to_string()
                    } else {
                        self.loops[m - n].names[0].name.clone()
                    }
                };
                let path = format_path(members.iter().map(|&m| label(m)));
                let loc = if members[0] < n {
                    self.nodes[members[0]].decl.loc
                } else {
                    self.loops[members[0] - n].names[0].loc
                };
                diags
                    .error(self.sources(), loc, format!("data-flow cycle: {path}"))
                    .node(label(members[0]))
                    .hint("a node cannot depend on its own output; keep state across frames in a variable (Set it in the exec list, read it with var(...))")
                    .emit();
            }
        }
        let mut acyclic = g.clone();
        acyclic.retain_nodes(|gr, x| !in_cycle[gr[x]]);
        let order = toposort(&acyclic, None).unwrap_or_default();
        for x in order {
            self.resolve_one(acyclic[x], diags);
        }
        for (i, c) in in_cycle.iter().enumerate() {
            if *c && i < n {
                self.nodes[i].failed = true;
            }
        }
    }

    /// Resolves node `i`, or loop `i - n` for `i` past the `n` nodes.
    fn resolve_one(&mut self, i: usize, diags: &mut Diagnostics) {
        let n = self.nodes.len();
        if i < n {
            self.resolve_node(i, diags);
        } else {
            self.resolve_loop(i - n, diags);
        }
    }

    fn resolve_loop(&mut self, lp: usize, diags: &mut Diagnostics) {
        let l = &self.loops[lp];
        if l.is_for {
            return;
        }
        let items = l.items;
        match self.expr_type(items, diags) {
            Some(Ok(ValueType::Array(e))) => self.loops[lp].element = Some(e.scalar()),
            Some(Ok(other)) => diags
                .error(
                    self.sources(),
                    items.loc,
                    format!("ForEach `items` must be an array, found {other}"),
                )
                .pin("items")
                .emit(),
            Some(Err(lit)) => {
                if let Some(ValueType::Array(e)) = literal::natural_type(lit) {
                    self.loops[lp].element = Some(e.scalar());
                } else {
                    diags
                        .error(
                            self.sources(),
                            items.loc,
                            "ForEach `items` must be an array",
                        )
                        .pin("items")
                        .emit();
                }
            }
            None => {}
        }
    }

    /// The type of a link or variable expression (`Ok`), or the literal to be typed by
    /// its pin (`Err`); `None` after reporting an error (or when the source failed).
    fn expr_type<'e>(
        &self,
        e: &'e Expr,
        diags: &mut Diagnostics,
    ) -> Option<Result<ValueType, &'e strider_graph::Literal>> {
        match self.source(e, diags)? {
            Ok(arg) => Some(Ok(arg.ty)),
            Err(lit) => Some(Err(lit)),
        }
    }

    /// Resolves an expression to a typed source, or hands back a literal to be typed by the
    /// pin. `None` after reporting an error, or silently when it depends on a failed node.
    fn source<'e>(
        &self,
        e: &'e Expr,
        diags: &mut Diagnostics,
    ) -> Option<Result<Arg, &'e strider_graph::Literal>> {
        match &e.kind {
            ExprKind::Literal(l) => Some(Err(l)),
            ExprKind::Var(name) => {
                if let Some(&i) = self.locals.get(name) {
                    let f = self.function?;
                    let ty = f.locals.iter().find(|l| &l.name.name == name)?.ty;
                    return Some(Ok(Arg {
                        src: Src::Local(i),
                        ty,
                        to_float: false,
                    }));
                }
                if let Some(&i) = self.ctx.global_index.get(name) {
                    return Some(Ok(Arg {
                        src: Src::Global(i),
                        ty: self.ctx.globals[i].ty,
                        to_float: false,
                    }));
                }
                let candidates = self
                    .ctx
                    .globals
                    .iter()
                    .map(|g| g.name.as_str())
                    .chain(self.locals.keys().map(String::as_str));
                let hint = suggest(name, candidates)
                    .map(|s| format!("did you mean `{s}`?"))
                    .unwrap_or_else(|| {
                        format!("declare it in `variables: {{ \"{name}\": (type: Float), }}`")
                    });
                diags
                    .error(self.sources(), e.loc, format!("unknown variable `{name}`"))
                    .hint(hint)
                    .emit();
                None
            }
            ExprKind::Link { source, pin } => {
                let Some(name) = self.names.get(source.as_str()) else {
                    let mut hint = suggest(source, self.names.keys().copied())
                        .map(|s| format!("did you mean `{s}`?"));
                    if hint.is_none() && self.ctx.global_index.contains_key(source) {
                        hint = Some(format!("`{source}` is a variable: write var(\"{source}\")"));
                    }
                    diags
                        .error(self.sources(), e.loc, format!("link to unknown node `{source}`"))
                        .maybe_hint(hint.or_else(|| Some("a link names a node id in this scope, a function input or a loop name".into())))
                        .emit();
                    return None;
                };
                match *name {
                    Name::Node(j) => {
                        let slot = &self.nodes[j];
                        let node = slot.resolved.as_ref()?;
                        let out = match pin {
                            None => {
                                if node.outputs.is_empty() {
                                    diags
                                        .error(
                                            self.sources(),
                                            e.loc,
                                            format!(
                                                "node `{source}` ({}) has no output to link to",
                                                slot.decl.kind.name
                                            ),
                                        )
                                        .emit();
                                    return None;
                                }
                                0
                            }
                            Some(p) => {
                                let names = self.output_names(j);
                                match names.iter().position(|n| n == p) {
                                    Some(o) => o,
                                    None => {
                                        let hint = suggest(p, names.iter().map(String::as_str))
                                            .map(|s| format!("did you mean `{source}.{s}`?"))
                                            .unwrap_or_else(|| {
                                                format!("its outputs are: {}", names.join(", "))
                                            });
                                        diags
                                            .error(self.sources(), e.loc, format!("link to unknown pin `{p}` of node `{source}` ({})", slot.decl.kind.name))
                                            .node(source.clone())
                                            .pin(p.clone())
                                            .hint(hint)
                                            .emit();
                                        return None;
                                    }
                                }
                            }
                        };
                        Some(Ok(Arg {
                            src: Src::Node { node: j, out },
                            ty: node.outputs[out],
                            to_float: false,
                        }))
                    }
                    Name::Input(i) => {
                        if let Some(p) = pin {
                            diags
                                .error(
                                    self.sources(),
                                    e.loc,
                                    format!("function input `{source}` has no pin `{p}`"),
                                )
                                .emit();
                            return None;
                        }
                        let ty = self.function?.inputs[i].ty;
                        Some(Ok(Arg {
                            src: Src::Input(i),
                            ty,
                            to_float: false,
                        }))
                    }
                    Name::Loop(lp, part) => {
                        if let Some(p) = pin {
                            diags
                                .error(
                                    self.sources(),
                                    e.loc,
                                    format!("loop name `{source}` has no pin `{p}`"),
                                )
                                .emit();
                            return None;
                        }
                        let ty = match part {
                            LoopPart::Element => self.loops[lp].element?,
                            LoopPart::Index | LoopPart::Count => ValueType::Int,
                        };
                        Some(Ok(Arg {
                            src: Src::Loop { lp, part },
                            ty,
                            to_float: false,
                        }))
                    }
                }
            }
        }
    }

    fn output_names(&self, j: usize) -> Vec<String> {
        let decl = self.nodes[j].decl;
        if let Some(&f) = self.ctx.fn_index.get(&decl.kind.name) {
            return self.ctx.fns[f]
                .decl
                .outputs
                .iter()
                .map(|p| p.name.name.clone())
                .collect();
        }
        if let (Some(spec), Some(NodeKind::Builtin(op))) = (
            registry().get(&decl.kind.name),
            self.nodes[j].resolved.as_ref().map(|r| r.kind),
        ) && let Some(o) = spec.overloads.iter().find(|o| o.op == op)
        {
            return o.outputs.iter().map(|p| p.name.to_string()).collect();
        }
        Vec::new()
    }

    fn resolve_node(&mut self, i: usize, diags: &mut Diagnostics) {
        let decl = self.nodes[i].decl;
        let label = decl.label();
        let kind = &decl.kind.name;
        // Sources of every pin, resolved once (errors reported once).
        let mut given: Vec<(&PinArg, Option<Result<Arg, &strider_graph::Literal>>)> =
            Vec::with_capacity(decl.pins.len());
        let mut failed_source = false;
        for p in &decl.pins {
            let before = diags.len();
            let s = self.source(&p.value, diags);
            diags.annotate_since(before, label, &p.name.name);
            if s.is_none() {
                failed_source = true;
            }
            given.push((p, s));
        }
        if let Some(&f) = self.ctx.fn_index.get(kind) {
            self.resolve_call(i, f, &given, failed_source, diags);
            return;
        }
        let Some(spec) = registry().get(kind) else {
            let fn_names = self.ctx.fns.iter().map(|f| f.decl.name.name.as_str());
            let all: Vec<&str> = registry()
                .nodes()
                .iter()
                .map(|n| n.name)
                .chain(fn_names)
                .collect();
            let hint = suggest(kind, all.iter().copied())
                .map(|s| format!("did you mean `{s}`?"))
                .unwrap_or_else(|| "see `strider nodes` for the node types".into());
            let what = if parse_statement(kind) {
                format!("`{kind}` is an exec statement, not a node")
            } else {
                format!("unknown node type `{kind}`")
            };
            diags
                .error(self.sources(), decl.kind.loc, what)
                .node(label)
                .hint(hint)
                .emit();
            self.nodes[i].failed = true;
            return;
        };
        // Unknown pins, against the node's pin names (shared by all overloads).
        let first = &spec.overloads[0];
        let mut bad = false;
        for (p, _) in &given {
            if !first.inputs.iter().any(|s| s.name == p.name.name) {
                let names: Vec<&str> = first.inputs.iter().map(|s| s.name).collect();
                let is_output = first.outputs.iter().any(|o| o.name == p.name.name);
                let hint = if is_output {
                    format!(
                        "`{}` is an output of {kind}; link to it from another node as \"{label}.{}\"",
                        p.name.name, p.name.name
                    )
                } else {
                    suggest(&p.name.name, names.iter().copied())
                        .map(|s| format!("did you mean `{s}`?"))
                        .unwrap_or_else(|| {
                            if names.is_empty() {
                                format!("{kind} has no inputs")
                            } else {
                                format!("{kind} has the inputs: {}", names.join(", "))
                            }
                        })
                };
                diags
                    .error(
                        self.sources(),
                        p.name.loc,
                        format!("unknown pin `{}` on {kind}", p.name.name),
                    )
                    .node(label)
                    .pin(p.name.name.clone())
                    .hint(hint)
                    .emit();
                bad = true;
            }
        }
        // Required inputs.
        for pin in first.inputs.iter().filter(|p| p.default.is_none()) {
            if !given.iter().any(|(p, _)| p.name.name == pin.name) {
                diags
                    .error(
                        self.sources(),
                        decl.loc,
                        format!("missing required input `{}` of {kind}", pin.name),
                    )
                    .node(label)
                    .pin(pin.name)
                    .hint(format!("add `{}: ...` ({}: {})", pin.name, pin.ty, pin.doc))
                    .emit();
                bad = true;
            }
        }
        // Target pins must be variables.
        for (p, source) in &given {
            let given_type = match source {
                Some(Ok(a)) if a.ty.is_array() => Some(a.ty),
                _ => None,
            };
            if let Some(pin) = first
                .inputs
                .iter()
                .find(|s| s.name == p.name.name && s.target)
                && !matches!(p.value.kind, ExprKind::Var(_))
            {
                diags
                        .error(self.sources(), p.value.loc, format!("write to a non-variable: {kind} changes its `{}` input in place, so it must be a variable", pin.name))
                        .node(label)
                        .pin(pin.name)
                        .hint(match given_type {
                            Some(ty) => format!("write `{}: var(\"Name\")` with a {ty} variable", pin.name),
                            None => format!("write `{}: var(\"Name\")` with a {} variable", pin.name, pin.ty),
                        })
                        .emit();
                bad = true;
            }
        }
        if bad || failed_source {
            self.nodes[i].failed = true;
            return;
        }
        // Overload resolution: first best fit (fewest promotions). An overload whose inputs
        // cannot take the types linked to them is passed over before anything is bound
        // (overloads name their pins alike and in one order).
        let linked: SmallVec<[(usize, ValueType); 8]> = first
            .inputs
            .iter()
            .enumerate()
            .filter_map(
                |(pi, pin)| match given.iter().find(|(p, _)| p.name.name == pin.name) {
                    Some((_, Some(Ok(a)))) => Some((pi, a.ty)),
                    _ => None,
                },
            )
            .collect();
        let mut best: Option<(usize, usize, Vec<Arg>)> = None;
        for (oi, o) in spec.overloads.iter().enumerate() {
            let takes = |&(pi, ty): &(usize, ValueType)| {
                let want = o.inputs[pi].ty;
                ty == want || ty.converts_to(want)
            };
            if linked.iter().all(takes)
                && let Ok((args, promotions)) = self.bind(o.inputs.as_slice(), &given)
                && best.as_ref().is_none_or(|(_, p, _)| promotions < *p)
            {
                best = Some((oi, promotions, args));
            }
        }
        match best {
            Some((oi, _, args)) => {
                let o = &spec.overloads[oi];
                self.nodes[i].resolved = Some(CNode {
                    kind: NodeKind::Builtin(o.op),
                    pure: spec.effect == Effect::Pure,
                    inputs: args,
                    outputs: o.outputs.iter().map(|p| p.ty).collect(),
                    state: o.state.clone(),
                });
            }
            None => {
                self.report_mismatch(spec, &given, label, decl, diags);
                self.nodes[i].failed = true;
            }
        }
    }

    /// Binds given pins to an overload's inputs: (args in pin order, promotions) or the
    /// first mismatch (pin index, message).
    fn bind(
        &self,
        pins: &[PinSpec],
        given: &[(&PinArg, Option<Result<Arg, &strider_graph::Literal>>)],
    ) -> Result<(Vec<Arg>, usize), (usize, Mismatch)> {
        let mut args = Vec::with_capacity(pins.len());
        let mut promotions = 0;
        for (pi, pin) in pins.iter().enumerate() {
            let g = given.iter().find(|(p, _)| p.name.name == pin.name);
            let arg = match g {
                None => {
                    let value = pin.default.clone().unwrap_or_else(|| pin.ty.zero());
                    Arg::constant(value, pin.ty, None)
                }
                Some((p, Some(Ok(a)))) => {
                    if a.ty == pin.ty {
                        a.clone()
                    } else if a.ty.converts_to(pin.ty) {
                        promotions += 1;
                        Arg {
                            to_float: true,
                            ..a.clone()
                        }
                    } else {
                        let _ = p;
                        return Err((
                            pi,
                            Mismatch::Types {
                                expected: pin.ty,
                                found: a.ty,
                            },
                        ));
                    }
                }
                Some((_, Some(Err(lit)))) => match literal::convert(lit, pin.ty, pin.choices) {
                    Ok((value, fit)) => {
                        if fit == Fit::Promoted {
                            promotions += 1;
                        }
                        Arg::constant(value, pin.ty, Some(lit.loc))
                    }
                    Err(m) => return Err((pi, Mismatch::Literal(m))),
                },
                Some((_, None)) => return Err((pi, Mismatch::Unresolved)),
            };
            args.push(arg);
        }
        Ok((args, promotions))
    }

    fn report_mismatch(
        &self,
        spec: &strider_nodes::NodeSpec,
        given: &[(&PinArg, Option<Result<Arg, &strider_graph::Literal>>)],
        label: &str,
        decl: &NodeDecl,
        diags: &mut Diagnostics,
    ) {
        let kind = spec.name;
        if spec.overloads.len() == 1 {
            if let Err((pi, msg)) = self.bind(&spec.overloads[0].inputs, given) {
                let pin = &spec.overloads[0].inputs[pi];
                let at = given
                    .iter()
                    .find(|(p, _)| p.name.name == pin.name)
                    .map_or(decl.loc, |(p, _)| p.value.loc);
                let hint = conversion_hint(
                    pin.ty,
                    given
                        .iter()
                        .find(|(p, _)| p.name.name == pin.name)
                        .and_then(|(_, s)| s.as_ref()),
                );
                diags
                    .error(
                        self.sources(),
                        at,
                        format!("type mismatch on pin `{}` of {kind}: {msg}", pin.name),
                    )
                    .node(label.to_string())
                    .pin(pin.name)
                    .maybe_hint(hint)
                    .emit();
            }
            return;
        }
        // A literal of the right kind that is malformed (e.g. a quaternion that is not
        // unit length) is the real problem: say that rather than "no overload fits".
        for o in &spec.overloads {
            if let Err((pi, msg)) = self.bind(&o.inputs, given) {
                let pin = &o.inputs[pi];
                if let Some((p, Some(Err(lit)))) =
                    given.iter().find(|(p, _)| p.name.name == pin.name)
                    && literal::natural_type(lit) == Some(pin.ty)
                    && !matches!(msg, Mismatch::Unresolved)
                {
                    diags
                        .error(
                            self.sources(),
                            p.value.loc,
                            format!("invalid value for pin `{}` of {kind}: {msg}", pin.name),
                        )
                        .node(label.to_string())
                        .pin(pin.name)
                        .emit();
                    return;
                }
            }
        }
        let found: Vec<String> = spec.overloads[0]
            .inputs
            .iter()
            .filter_map(|pin| {
                given
                    .iter()
                    .find(|(p, _)| p.name.name == pin.name)
                    .map(|(p, s)| {
                        let t = match s {
                            Some(Ok(a)) => a.ty.name().to_string(),
                            Some(Err(l)) => literal::natural_type(l)
                                .map_or_else(|| literal::describe(l), |t| t.name().to_string()),
                            None => "?".into(),
                        };
                        format!("{}: {t}", p.name.name)
                    })
            })
            .collect();
        let sigs: Vec<String> = spec
            .overloads
            .iter()
            .map(|o| {
                format!(
                    "({})",
                    o.inputs
                        .iter()
                        .map(|p| format!("{}: {}", p.name, p.ty))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })
            .collect();
        let hint = given.iter().find_map(|(_, s)| match s {
            Some(Ok(a)) if a.ty == ValueType::Float && spec.overloads.iter().any(|o| o.inputs.iter().any(|p| p.ty == ValueType::Vec3)) => {
                Some("to combine a Float with a Vec3, use Scale(value: vector, factor: float) or build a vector with MakeVector".to_string())
            }
            _ => None,
        });
        diags
            .error(
                self.sources(),
                decl.loc,
                format!("type mismatch: {kind} does not take ({})", found.join(", ")),
            )
            .node(label.to_string())
            .hint(match hint {
                Some(h) => format!("{h}; {kind} takes {}", sigs.join(" or ")),
                None => format!("{kind} takes {}", sigs.join(" or ")),
            })
            .emit();
    }

    fn resolve_call(
        &mut self,
        i: usize,
        f: usize,
        given: &[(&PinArg, Option<Result<Arg, &strider_graph::Literal>>)],
        failed_source: bool,
        diags: &mut Diagnostics,
    ) {
        let decl = self.nodes[i].decl;
        let label = decl.label().to_string();
        let sig = &self.ctx.fns[f];
        let fd = sig.decl;
        let mut bad = failed_source;
        for (p, _) in given {
            if !fd.inputs.iter().any(|q| q.name.name == p.name.name) {
                let names: Vec<&str> = fd.inputs.iter().map(|q| q.name.name.as_str()).collect();
                diags
                    .error(
                        self.sources(),
                        p.name.loc,
                        format!(
                            "wrong arguments: function `{}` has no input `{}`",
                            fd.name.name, p.name.name
                        ),
                    )
                    .node(label.clone())
                    .pin(p.name.name.clone())
                    .hint(match suggest(&p.name.name, names.iter().copied()) {
                        Some(s) => format!("did you mean `{s}`?"),
                        None => format!(
                            "`{}` takes {} input(s): {}",
                            fd.name.name,
                            names.len(),
                            names.join(", ")
                        ),
                    })
                    .emit();
                bad = true;
            }
        }
        let mut args = Vec::new();
        for q in &fd.inputs {
            let g = given.iter().find(|(p, _)| p.name.name == q.name.name);
            let arg = match g {
                None => match &q.default {
                    Some(lit) => match literal::convert(lit, q.ty, &[]) {
                        Ok((value, _)) => Arg::constant(value, q.ty, Some(lit.loc)),
                        Err(m) => {
                            diags
                                .error(
                                    self.sources(),
                                    lit.loc,
                                    format!("default of input `{}`: {m}", q.name.name),
                                )
                                .emit();
                            bad = true;
                            continue;
                        }
                    },
                    None => {
                        let names: Vec<String> = fd
                            .inputs
                            .iter()
                            .map(|q| format!("{}: {}", q.name.name, q.ty))
                            .collect();
                        diags
                            .error(
                                self.sources(),
                                decl.loc,
                                format!(
                                    "wrong arguments: call of `{}` is missing input `{}`",
                                    fd.name.name, q.name.name
                                ),
                            )
                            .node(label.clone())
                            .pin(q.name.name.clone())
                            .hint(format!("`{}` takes ({})", fd.name.name, names.join(", ")))
                            .emit();
                        bad = true;
                        continue;
                    }
                },
                Some((_, None)) => continue,
                Some((p, Some(Ok(a)))) => {
                    if a.ty == q.ty {
                        a.clone()
                    } else if a.ty.converts_to(q.ty) {
                        Arg {
                            to_float: true,
                            ..a.clone()
                        }
                    } else {
                        diags
                            .error(
                                self.sources(),
                                p.value.loc,
                                format!(
                                    "type mismatch on input `{}` of `{}`: expected {}, found {}",
                                    q.name.name, fd.name.name, q.ty, a.ty
                                ),
                            )
                            .node(label.clone())
                            .pin(q.name.name.clone())
                            .maybe_hint(conversion_hint(q.ty, Some(&Ok(a.clone()))))
                            .emit();
                        bad = true;
                        continue;
                    }
                }
                Some((_, Some(Err(lit)))) => match literal::convert(lit, q.ty, &[]) {
                    Ok((value, _)) => Arg::constant(value, q.ty, Some(lit.loc)),
                    Err(m) => {
                        diags
                            .error(
                                self.sources(),
                                lit.loc,
                                format!(
                                    "type mismatch on input `{}` of `{}`: {m}",
                                    q.name.name, fd.name.name
                                ),
                            )
                            .node(label.clone())
                            .pin(q.name.name.clone())
                            .emit();
                        bad = true;
                        continue;
                    }
                },
            };
            args.push(arg);
        }
        if bad {
            self.nodes[i].failed = true;
            return;
        }
        self.nodes[i].resolved = Some(CNode {
            kind: NodeKind::Call(f),
            pure: sig.pure,
            inputs: args,
            outputs: fd.outputs.iter().map(|p| p.ty).collect(),
            state: Vec::new(),
        });
    }

    /// An argument for a step input of a fixed type.
    fn step_arg(
        &self,
        e: &Expr,
        ty: ValueType,
        what: &str,
        diags: &mut Diagnostics,
    ) -> Option<Arg> {
        match self.source(e, diags)? {
            Ok(a) if a.ty == ty => Some(a),
            Ok(a) if a.ty.converts_to(ty) => Some(Arg {
                to_float: true,
                ..a
            }),
            Ok(a) => {
                diags
                    .error(
                        self.sources(),
                        e.loc,
                        format!("type mismatch: {what} expects {ty}, found {}", a.ty),
                    )
                    .emit();
                None
            }
            Err(lit) => match literal::convert(lit, ty, &[]) {
                Ok((value, _)) => Some(Arg::constant(value, ty, Some(lit.loc))),
                Err(m) => {
                    diags
                        .error(
                            self.sources(),
                            lit.loc,
                            format!("type mismatch: {what}: {m}"),
                        )
                        .emit();
                    None
                }
            },
        }
    }

    /// Checks that the pure nodes an argument pulls read loop names only inside their loop.
    /// Iterative, so arbitrarily long data-flow chains cannot overflow the stack.
    fn check_scope(&self, arg: &Arg, active: &[usize], at: Loc, diags: &mut Diagnostics) {
        if self.loops.is_empty() {
            return; // no loop names to misuse
        }
        let mut seen = FixedBitSet::with_capacity(self.nodes.len());
        let mut stack: Vec<(&Arg, Loc)> = vec![(arg, at)];
        while let Some((arg, at)) = stack.pop() {
            match &arg.src {
                Src::Loop { lp, .. } if !active.contains(lp) => {
                    let decl = &self.loops[*lp].names[0];
                    diags
                        .error(self.sources(), at, format!("`{}` is used outside its loop", decl.name))
                        .hint(format!(
                            "loop names exist only inside the body of the loop that declares them (at {})",
                            self.sources().describe(decl.loc)
                        ))
                        .emit();
                }
                Src::Node { node, .. } if !seen.put(*node) => {
                    if let Some(n) = &self.nodes[*node].resolved
                        && n.pure
                    {
                        let loc = self.nodes[*node].decl.loc;
                        stack.extend(n.inputs.iter().map(|a| (a, loc)));
                    }
                }
                _ => {}
            }
        }
    }

    fn steps(
        &mut self,
        steps: &'a [Step],
        active: &mut Vec<usize>,
        diags: &mut Diagnostics,
    ) -> Vec<CStep> {
        let mut out = Vec::new();
        for s in steps {
            if let Some(c) = self.step(s, active, diags) {
                out.push(c);
            }
        }
        out
    }

    fn step(
        &mut self,
        s: &'a Step,
        active: &mut Vec<usize>,
        diags: &mut Diagnostics,
    ) -> Option<CStep> {
        match s {
            Step::Set { var, value, loc } => {
                let target = if let Some(&i) = self.locals.get(&var.name) {
                    let ty = self
                        .function?
                        .locals
                        .iter()
                        .find(|l| l.name.name == var.name)?
                        .ty;
                    (VarRef::Local(i), ty)
                } else if let Some(&i) = self.ctx.global_index.get(&var.name) {
                    (VarRef::Global(i), self.ctx.globals[i].ty)
                } else {
                    let what = match self.names.get(var.name.as_str()) {
                        Some(Name::Node(_)) => Some("a node"),
                        Some(Name::Input(_)) => Some("a function input"),
                        Some(Name::Loop(..)) => Some("a loop name"),
                        None => None,
                    };
                    match what {
                        Some(w) => diags
                            .error(self.sources(), var.loc, format!("write to a non-variable: `{}` is {w}", var.name))
                            .hint("Set writes variables declared in `variables` (or a function's `locals`)")
                            .emit(),
                        None => {
                            let candidates = self.ctx.globals.iter().map(|g| g.name.as_str()).chain(self.locals.keys().map(String::as_str));
                            let hint = suggest(&var.name, candidates).map(|s| format!("did you mean `{s}`?"));
                            diags
                                .error(self.sources(), var.loc, format!("unknown variable `{}`", var.name))
                                .maybe_hint(hint.or_else(|| Some(format!("declare it in `variables: {{ \"{}\": (type: ...), }}`", var.name))))
                                .emit();
                        }
                    }
                    return None;
                };
                let arg =
                    self.step_arg(value, target.1, &format!("Set(\"{}\")", var.name), diags)?;
                self.check_scope(&arg, active, *loc, diags);
                Some(CStep::Set {
                    target: target.0,
                    ty: target.1,
                    arg,
                })
            }
            Step::Run(id) => {
                let Some(Name::Node(j)) = self.names.get(id.name.as_str()).copied() else {
                    let hint = suggest(&id.name, self.names.keys().copied())
                        .map(|s| format!("did you mean `{s}`?"));
                    diags
                        .error(
                            self.sources(),
                            id.loc,
                            format!("Run names unknown node `{}`", id.name),
                        )
                        .maybe_hint(hint)
                        .emit();
                    return None;
                };
                self.nodes[j].ran = true;
                let node = self.nodes[j].resolved.clone()?;
                if node.pure {
                    diags
                        .error(self.sources(), id.loc, format!("pure node used as exec: `{}` ({}) only computes a value", id.name, self.nodes[j].decl.kind.name))
                        .node(id.name.clone())
                        .hint("pure nodes run when a step needs their output; remove the Run, or link the value into a Set or a mutating node")
                        .emit();
                    return None;
                }
                for a in &node.inputs {
                    self.check_scope(a, active, id.loc, diags);
                }
                Some(CStep::Exec(j))
            }
            Step::Node(n) => {
                let j = *self.inline_index.get(&(n as *const _))?;
                let node = self.nodes[j].resolved.clone()?;
                if node.pure && matches!(node.kind, NodeKind::Builtin(_)) {
                    diags
                        .error(self.sources(), n.loc, format!("pure node used as exec: {} only computes a value, and has no effect in an exec list", n.kind.name))
                        .node(n.label().to_string())
                        .hint("declare it in `nodes` with an id and link its output where it is needed")
                        .emit();
                    return None;
                }
                for a in &node.inputs {
                    self.check_scope(a, active, n.loc, diags);
                }
                Some(CStep::Exec(j))
            }
            Step::Branch {
                condition,
                then,
                otherwise,
                loc,
            } => {
                let c = self.step_arg(condition, ValueType::Bool, "Branch condition", diags);
                if let Some(c) = &c {
                    self.check_scope(c, active, *loc, diags);
                }
                let then = self.steps(then, active, diags);
                let otherwise = self.steps(otherwise, active, diags);
                Some(CStep::Branch {
                    condition: c?,
                    then,
                    otherwise,
                })
            }
            Step::ForEach {
                items, body, loc, ..
            } => {
                let lp = *self.loop_index.get(&(s as *const _))?;
                let items_arg = match self.source(items, diags) {
                    Some(Ok(a)) => Some(a),
                    Some(Err(lit)) => {
                        let ty = literal::natural_type(lit).filter(|t| t.is_array());
                        match ty.map(|t| literal::convert(lit, t, &[])) {
                            Some(Ok((value, _))) => Some(Arg::constant(value, ty?, Some(lit.loc))),
                            _ => None,
                        }
                    }
                    None => None,
                };
                if let Some(a) = &items_arg {
                    self.check_scope(a, active, *loc, diags);
                }
                active.push(lp);
                let body = self.steps(body, active, diags);
                active.pop();
                let items_arg = items_arg?;
                if !items_arg.ty.is_array() {
                    return None;
                }
                self.loops[lp].element = items_arg.ty.elem().map(|e| e.scalar());
                Some(CStep::ForEach {
                    items: items_arg,
                    lp,
                    body,
                })
            }
            Step::For {
                count, body, loc, ..
            } => {
                let lp = *self.loop_index.get(&(s as *const _))?;
                let c = self.step_arg(count, ValueType::Int, "For count", diags);
                if let Some(c) = &c {
                    self.check_scope(c, active, *loc, diags);
                }
                active.push(lp);
                let body = self.steps(body, active, diags);
                active.pop();
                Some(CStep::For {
                    count: c?,
                    lp,
                    body,
                })
            }
            Step::Sequence(blocks, _) => {
                let blocks = blocks
                    .iter()
                    .map(|b| self.steps(b, active, diags))
                    .collect();
                Some(CStep::Sequence(blocks))
            }
            Step::Return { values, loc } => {
                let Some(f) = self.function else {
                    if let Some(v) = values.first() {
                        diags
                            .error(
                                self.sources(),
                                v.name.loc,
                                "an event has no outputs; `Return` in an event takes no values",
                            )
                            .hint("write `Return` to leave the event early")
                            .emit();
                        return None;
                    }
                    return Some(CStep::Return(Vec::new()));
                };
                let mut out = Vec::new();
                for v in values {
                    let Some(o) = f.outputs.iter().position(|p| p.name.name == v.name.name) else {
                        let names: Vec<&str> =
                            f.outputs.iter().map(|p| p.name.name.as_str()).collect();
                        diags
                            .error(
                                self.sources(),
                                v.name.loc,
                                format!(
                                    "function `{}` has no output `{}`",
                                    f.name.name, v.name.name
                                ),
                            )
                            .hint(if names.is_empty() {
                                "the function declares no outputs".to_string()
                            } else {
                                format!("its outputs are: {}", names.join(", "))
                            })
                            .emit();
                        continue;
                    };
                    let ty = f.outputs[o].ty;
                    if let Some(a) =
                        self.step_arg(&v.value, ty, &format!("output `{}`", v.name.name), diags)
                    {
                        self.check_scope(&a, active, *loc, diags);
                        out.push((o, a));
                    }
                }
                Some(CStep::Return(out))
            }
        }
    }
}

/// One actual cycle through a strongly connected component, following edges, starting
/// at the member with the lowest index and ending back at it (the start repeated last):
/// the shortest way back, found breadth-first.
fn cycle_path(g: &DiGraph<usize, ()>, scc: &[NodeIndex]) -> Vec<NodeIndex> {
    let start = *scc.iter().min_by_key(|v| g[**v]).unwrap_or(&scc[0]);
    let members: FxHashSet<NodeIndex> = scc.iter().copied().collect();
    let mut previous: FxHashMap<NodeIndex, NodeIndex> = FxHashMap::default();
    let mut queue = std::collections::VecDeque::from([start]);
    while let Some(v) = queue.pop_front() {
        let mut next: Vec<NodeIndex> = g.neighbors(v).filter(|w| members.contains(w)).collect();
        next.sort_by_key(|w| g[*w]);
        for w in next {
            if w == start {
                // Walk back from `v` to `start`, then turn it around: start → … → v → start.
                let mut path = vec![v];
                let mut cur = v;
                while cur != start {
                    cur = previous[&cur];
                    path.push(cur);
                }
                path.reverse();
                path.push(start);
                return path;
            }
            if let std::collections::hash_map::Entry::Vacant(e) = previous.entry(w) {
                e.insert(v);
                queue.push_back(w);
            }
        }
    }
    vec![start, start]
}

/// `a → b → c → a`, shortened in the middle for very long cycles.
fn format_path(names: impl ExactSizeIterator<Item = String>) -> String {
    let names: Vec<String> = names.collect();
    if names.len() <= 12 {
        return names.join(" → ");
    }
    let head = names[..6].join(" → ");
    let tail = names[names.len() - 3..].join(" → ");
    format!("{head} → … ({} more) → {tail}", names.len() - 9)
}

fn parse_statement(kind: &str) -> bool {
    [
        "Set", "Run", "Branch", "ForEach", "For", "Sequence", "Return",
    ]
    .contains(&kind)
}

fn conversion_hint(
    expected: ValueType,
    found: Option<&Result<Arg, &strider_graph::Literal>>,
) -> Option<String> {
    let found_ty = match found? {
        Ok(a) => a.ty,
        Err(l) => literal::natural_type(l)?,
    };
    Some(match (found_ty, expected) {
        (ValueType::Float, ValueType::Vec3) => {
            "insert a MakeVector node (e.g. MakeVector(z: ...)) to build a Vec3 from a Float".into()
        }
        (ValueType::Vec3, ValueType::Float) => {
            "take one component with BreakVector (\"node.x\") or the size with Length".into()
        }
        (ValueType::Float, ValueType::Int) => {
            "convert with ToInt (truncates) or Round then ToInt".into()
        }
        (ValueType::Transform, ValueType::Vec3) => {
            "take the position with BreakTransform (\"node.translation\")".into()
        }
        (ValueType::Transform, ValueType::Quat) => {
            "take the rotation with BreakTransform (\"node.rotation\")".into()
        }
        (ValueType::Vec3 | ValueType::Quat, ValueType::Transform) => {
            "build one with MakeTransform".into()
        }
        (ValueType::Array(_), t) if !t.is_array() => {
            "pick an element with At(array: ..., index: ...)".into()
        }
        _ => return None,
    })
}
