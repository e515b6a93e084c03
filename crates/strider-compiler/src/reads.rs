//! What a pure node's value depends on, beyond its own inputs: the graph variables, the
//! function locals and the pose it reads, directly or through the pure nodes and pure
//! function calls it pulls. Code generation keeps a pure node's value for later steps until
//! a step writes one of these (see `codegen.rs`).
//!
//! A function's inputs are constant while its body runs; constants, the frame's dt, the
//! world transform and the world (traces) are constant for a whole run, and stateful nodes
//! advance once per run, so none of them ends a value's life. Loop variables do, but values
//! are never kept across loop iterations.

use crate::check::{Body, CStep, Checked, NodeKind, Src};
use std::collections::HashMap;
use strider_nodes::Op;

/// The mutable state a value was computed from.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Reads {
    /// Graph variables (indices into `Checked::globals`), sorted, no duplicates.
    pub globals: Vec<usize>,
    /// Locals of the body the node sits in, sorted, no duplicates.
    pub locals: Vec<usize>,
    /// Exec nodes of the same body whose outputs it reads (as last written), sorted.
    pub execs: Vec<usize>,
    /// Whether it reads the pose (a bone transform).
    pub pose: bool,
}

impl Reads {
    fn merge(&mut self, other: &Reads) {
        self.globals.extend_from_slice(&other.globals);
        self.locals.extend_from_slice(&other.locals);
        self.execs.extend_from_slice(&other.execs);
        self.pose |= other.pose;
        self.normalise();
    }

    fn normalise(&mut self) {
        self.globals.sort_unstable();
        self.globals.dedup();
        self.locals.sort_unstable();
        self.locals.dedup();
        self.execs.sort_unstable();
        self.execs.dedup();
    }
}

/// Whether a built-in op reads the pose's current bone transforms. (`GetParent` and
/// `FindBones` read the skeleton, which never changes.)
pub(crate) fn reads_pose(op: Op) -> bool {
    matches!(op, Op::GetTransform)
}

/// Whether a mutating built-in op may change the pose. Draws and array edits do not;
/// anything else mutating is assumed to.
pub(crate) fn writes_pose(op: Op) -> bool {
    !matches!(
        op,
        Op::DrawPoint
            | Op::DrawLine
            | Op::DrawArrow
            | Op::DrawSphere
            | Op::DrawBox
            | Op::DrawSpline
            | Op::DrawTransform
            | Op::ArraySetAt(_)
            | Op::ArrayAdd(_)
            | Op::ArrayReset(_)
    )
}

/// Memoised [`Reads`] of every node of every body, and of whole pure function bodies.
#[derive(Default)]
pub(crate) struct ReadsTable {
    /// `(function or None for the graph, node)` → reads.
    nodes: HashMap<(Option<usize>, usize), Reads>,
    /// Function → the globals and pose its whole body reads (for calls of it).
    functions: HashMap<usize, Reads>,
}

impl ReadsTable {
    /// What node `n` of `body` (`None`: the graph) reads. Iterative, so long chains of pure
    /// nodes cannot overflow the stack; the checker guarantees they are acyclic.
    pub(crate) fn node(&mut self, checked: &Checked, body: Option<usize>, n: usize) -> Reads {
        if let Some(r) = self.nodes.get(&(body, n)) {
            return r.clone();
        }
        let b = body_of(checked, body);
        let mut stack = vec![(n, false)];
        while let Some((m, inputs_done)) = stack.pop() {
            if self.nodes.contains_key(&(body, m)) {
                continue;
            }
            let node = &b.nodes[m];
            if !inputs_done {
                stack.push((m, true));
                for a in &node.inputs {
                    if let Src::Node { node: dep, .. } = a.src
                        && b.nodes[dep].pure
                        && !self.nodes.contains_key(&(body, dep))
                    {
                        stack.push((dep, false));
                    }
                }
                continue;
            }
            let mut reads = Reads::default();
            for a in &node.inputs {
                match a.src {
                    Src::Global(g) => reads.globals.push(g),
                    Src::Local(l) => reads.locals.push(l),
                    Src::Node { node: dep, .. } if b.nodes[dep].pure => {
                        if let Some(r) = self.nodes.get(&(body, dep)) {
                            reads.merge(&r.clone());
                        }
                    }
                    // An exec node's outputs change when that node runs again.
                    Src::Node { node: dep, .. } => reads.execs.push(dep),
                    _ => {}
                }
            }
            match node.kind {
                NodeKind::Builtin(op) => reads.pose |= reads_pose(op),
                NodeKind::Call(f) => {
                    let callee = self.function(checked, f);
                    reads.globals.extend_from_slice(&callee.globals);
                    reads.pose |= callee.pose;
                }
            }
            reads.normalise();
            self.nodes.insert((body, m), reads);
        }
        self.nodes[&(body, n)].clone()
    }

    /// The graph variables and pose anything in function `f`'s body reads (its locals and
    /// inputs are its own and start afresh at every call).
    fn function(&mut self, checked: &Checked, f: usize) -> Reads {
        if let Some(r) = self.functions.get(&f) {
            return r.clone();
        }
        // The checker rejects recursion, so this terminates; calls nest only as deep as
        // the functions of the graph do.
        let b = &checked.functions[f];
        let mut reads = Reads::default();
        for n in 0..b.nodes.len() {
            let r = self.node(checked, Some(f), n);
            reads.globals.extend_from_slice(&r.globals);
            reads.pose |= r.pose;
            if let NodeKind::Builtin(op) = b.nodes[n].kind {
                reads.pose |= reads_pose(op);
            }
        }
        for_each_step_global(&b.exec, &mut |g| reads.globals.push(g));
        reads.normalise();
        self.functions.insert(f, reads.clone());
        reads
    }
}

fn body_of(checked: &Checked, body: Option<usize>) -> &Body {
    match body {
        None => &checked.graph,
        Some(f) => &checked.functions[f],
    }
}

/// Calls `each` with every graph variable the steps read directly.
fn for_each_step_global(steps: &[CStep], each: &mut impl FnMut(usize)) {
    let mut arg = |a: &crate::check::Arg| {
        if let Src::Global(g) = a.src {
            each(g);
        }
    };
    let mut lists: Vec<&[CStep]> = vec![steps];
    while let Some(list) = lists.pop() {
        for s in list {
            match s {
                CStep::Set { arg: a, .. } => arg(a),
                CStep::Exec(_) => {}
                CStep::Branch {
                    condition,
                    then,
                    otherwise,
                } => {
                    arg(condition);
                    lists.push(then);
                    lists.push(otherwise);
                }
                CStep::ForEach { items, body, .. } => {
                    arg(items);
                    lists.push(body);
                }
                CStep::For { count, body, .. } => {
                    arg(count);
                    lists.push(body);
                }
                CStep::Sequence(blocks) => lists.extend(blocks.iter().map(Vec::as_slice)),
                CStep::Return(values) => values.iter().for_each(|(_, a)| arg(a)),
            }
        }
    }
}
