//! What a pure node's value depends on, beyond its own inputs: the graph variables, the
//! function locals and the pose it reads, directly or through the pure nodes and pure
//! function calls it pulls. Code generation keeps a pure node's value for later steps until
//! a step writes one of these (see `codegen.rs`).
//!
//! A function's inputs are constant while its body runs; constants, the frame's dt, the
//! world transform and the world (traces) are constant for a whole run, and stateful nodes
//! advance once per run, so none of them ends a value's life. Loop variables do, but values
//! are never kept across loop iterations.

use crate::check::{Body, CStep, Checked, NodeKind, Src, VarRef};
use fixedbitset::FixedBitSet;
use rustc_hash::FxHashMap;
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
    /// Whether it reads a loop's element, index or count.
    pub loop_vars: bool,
    /// Whether it is or pulls a stateful node (whose state advances when first evaluated
    /// in a run, so it must not be evaluated where the graph would not evaluate it).
    pub stateful: bool,
}

impl Reads {
    /// Adds what `other` reads; [`Reads::normalise`] must follow.
    fn add(&mut self, other: &Reads) {
        self.globals.extend_from_slice(&other.globals);
        self.locals.extend_from_slice(&other.locals);
        self.execs.extend_from_slice(&other.execs);
        self.pose |= other.pose;
        self.loop_vars |= other.loop_vars;
        self.stateful |= other.stateful;
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

/// What running a list of steps may change in its frame: the other side of [`Reads`].
#[derive(Clone, Debug, Default)]
pub(crate) struct Writes {
    /// Variables and locals set, or edited in place by a mutating node.
    pub vars: Vec<VarRef>,
    /// Exec nodes run (their outputs change).
    pub execs: Vec<usize>,
    /// The pose may move.
    pub pose: bool,
    /// Any graph variable may change (an impure function call).
    pub any_global: bool,
    /// A mutating node edits a pure node's output in place: nothing is safe to keep.
    pub everything: bool,
}

impl Writes {
    /// Whether a value that reads `r` may be changed by these writes.
    pub(crate) fn touch(&self, r: &Reads) -> bool {
        self.everything
            || (self.pose && r.pose)
            || (self.any_global && !r.globals.is_empty())
            || self.execs.iter().any(|e| r.execs.binary_search(e).is_ok())
            || self.vars.iter().any(|v| match v {
                VarRef::Global(g) => r.globals.binary_search(g).is_ok(),
                VarRef::Local(l) => r.locals.binary_search(l).is_ok(),
            })
    }

    /// Adds what `steps` of `body` may change (nested lists included; function bodies are
    /// summarised by their call: an impure call may change any variable and the pose).
    pub(crate) fn collect(&mut self, body: &Body, steps: &[CStep]) {
        each_step(steps, |s| match s {
            CStep::Set { target, .. } => self.vars.push(*target),
            CStep::Exec(n) => {
                self.execs.push(*n);
                let node = &body.nodes[*n];
                match node.kind {
                    NodeKind::Builtin(op) => {
                        // Only arrays are edited in place (a node's `target` pins, which
                        // the checker requires to be variables); a scalar input is only
                        // read.
                        for a in node.inputs.iter().filter(|a| a.ty.is_array()) {
                            match a.src {
                                Src::Global(g) => self.vars.push(VarRef::Global(g)),
                                Src::Local(l) => self.vars.push(VarRef::Local(l)),
                                Src::Node { .. } => self.everything = true,
                                _ => {}
                            }
                        }
                        self.pose |= writes_pose(op);
                    }
                    NodeKind::Call(_) => {
                        self.any_global |= !node.pure;
                        self.pose |= !node.pure;
                    }
                }
            }
            _ => {}
        });
    }
}

/// Calls `each` with every step of `steps`, those of nested lists (branch arms, loop
/// bodies, sequence blocks) included: each list in order, nested lists after it.
pub(crate) fn each_step<'s>(steps: &'s [CStep], mut each: impl FnMut(&'s CStep)) {
    let mut lists: Vec<&[CStep]> = vec![steps];
    while let Some(list) = lists.pop() {
        for s in list {
            each(s);
            match s {
                CStep::Branch {
                    then, otherwise, ..
                } => {
                    lists.push(then);
                    lists.push(otherwise);
                }
                CStep::ForEach { body, .. } | CStep::For { body, .. } => lists.push(body),
                CStep::Sequence(blocks) => lists.extend(blocks.iter().map(Vec::as_slice)),
                CStep::Set { .. } | CStep::Exec(_) | CStep::Return(_) => {}
            }
        }
    }
}

/// Calls `each` with the arguments `step` reads itself: a `Set`'s value, a branch's
/// condition, a loop's items or count, a `Return`'s values (not an exec node's inputs, nor
/// what nested steps read).
fn step_args(step: &CStep, mut each: impl FnMut(&crate::check::Arg)) {
    match step {
        CStep::Set { arg, .. } => each(arg),
        CStep::Branch { condition, .. } => each(condition),
        CStep::ForEach { items, .. } => each(items),
        CStep::For { count, .. } => each(count),
        CStep::Return(values) => values.iter().for_each(|(_, a)| each(a)),
        CStep::Exec(_) | CStep::Sequence(_) => {}
    }
}

/// The pure nodes of `body` that `steps` (nested lists included) pull, with everything
/// they depend on, in increasing index order.
pub(crate) fn pulled_by(body: &Body, steps: &[CStep]) -> Vec<usize> {
    let mut roots = Vec::new();
    let mut arg = |a: &crate::check::Arg| {
        if let Src::Node { node, .. } = a.src {
            roots.push(node);
        }
    };
    each_step(steps, |s| match s {
        CStep::Exec(n) => body.nodes[*n].inputs.iter().for_each(&mut arg),
        _ => step_args(s, &mut arg),
    });
    let mut seen = vec![false; body.nodes.len()];
    let mut out = Vec::new();
    while let Some(n) = roots.pop() {
        if seen[n] || !body.nodes[n].pure {
            continue;
        }
        seen[n] = true;
        out.push(n);
        for a in &body.nodes[n].inputs {
            if let Src::Node { node, .. } = a.src {
                roots.push(node);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Memoised [`Reads`] of every node of every body, and of whole pure function bodies.
#[derive(Default)]
pub(crate) struct ReadsTable {
    /// Per body (the graph first, then each function), per node: its reads, once known.
    /// Indexed rather than hashed: code generation asks after every step it emits.
    nodes: Vec<Vec<Option<Reads>>>,
    /// Function → the globals and pose its whole body reads (for calls of it).
    functions: FxHashMap<usize, Reads>,
    /// Per body (as `nodes`): the inverse of `nodes`, once built (see [`Readers`]).
    readers: Vec<Option<Readers>>,
}

/// For everything a step may write, the pure nodes of one body whose values read it: the
/// inverse of [`Reads`]. Forgetting what a step changed is then a few word operations per
/// thing written, not a test of every kept value against it.
#[derive(Default)]
struct Readers {
    /// The nodes that read the pose.
    pose: FixedBitSet,
    /// The nodes that read any graph variable.
    any_global: FixedBitSet,
    /// Per graph variable, the nodes that read it (shorter when no node reads the later ones).
    globals: Vec<FixedBitSet>,
    /// Per local of the body, the nodes that read it.
    locals: Vec<FixedBitSet>,
    /// Per exec node of the body, the nodes that read its outputs.
    execs: Vec<FixedBitSet>,
}

impl Readers {
    /// Marks node `n` (of a body of `len` nodes) as a reader of item `key` of `sets`.
    fn mark(sets: &mut Vec<FixedBitSet>, key: usize, n: usize, len: usize) {
        if sets.len() <= key {
            sets.resize_with(key + 1, FixedBitSet::new);
        }
        if sets[key].is_empty() {
            sets[key].grow(len);
        }
        sets[key].insert(n);
    }
}

impl ReadsTable {
    /// What node `n` of `body` (`None`: the graph) reads. Iterative, so long chains of pure
    /// nodes cannot overflow the stack; the checker guarantees they are acyclic.
    pub(crate) fn node(&mut self, checked: &Checked, body: Option<usize>, n: usize) -> &Reads {
        let b = body_of(checked, body);
        let at = body.map_or(0, |f| f + 1);
        if self.nodes.len() <= at {
            self.nodes.resize_with(at + 1, Vec::new);
        }
        if self.nodes[at].is_empty() {
            self.nodes[at].resize_with(b.nodes.len(), || None);
        }
        if self.nodes[at][n].is_none() {
            self.fill(checked, b, at, n);
        }
        self.nodes[at][n].as_ref().expect("filled")
    }

    /// Removes from `kept` (pure nodes of `body` whose values are kept) those that `writes`
    /// may change: the nodes `n` with `writes.touch(self.node(checked, body, n))`.
    pub(crate) fn forget(
        &mut self,
        checked: &Checked,
        body: Option<usize>,
        writes: &Writes,
        kept: &mut FixedBitSet,
    ) {
        if writes.everything {
            kept.clear();
            return;
        }
        let r = self.readers(checked, body);
        if writes.pose {
            kept.difference_with(&r.pose);
        }
        if writes.any_global {
            kept.difference_with(&r.any_global);
        }
        for &e in &writes.execs {
            if let Some(set) = r.execs.get(e) {
                kept.difference_with(set);
            }
        }
        for v in &writes.vars {
            let set = match *v {
                VarRef::Global(g) => r.globals.get(g),
                VarRef::Local(l) => r.locals.get(l),
            };
            if let Some(set) = set {
                kept.difference_with(set);
            }
        }
    }

    /// The [`Readers`] of `body`, built on first use from the reads of its pure nodes.
    fn readers(&mut self, checked: &Checked, body: Option<usize>) -> &Readers {
        let at = body.map_or(0, |f| f + 1);
        if self.readers.len() <= at {
            self.readers.resize_with(at + 1, || None);
        }
        if self.readers[at].is_none() {
            let b = body_of(checked, body);
            let len = b.nodes.len();
            let mut r = Readers {
                pose: FixedBitSet::with_capacity(len),
                any_global: FixedBitSet::with_capacity(len),
                ..Readers::default()
            };
            for n in (0..len).filter(|&n| b.nodes[n].pure) {
                let reads = self.node(checked, body, n);
                r.pose.set(n, reads.pose);
                r.any_global.set(n, !reads.globals.is_empty());
                for &g in &reads.globals {
                    Readers::mark(&mut r.globals, g, n, len);
                }
                for &l in &reads.locals {
                    Readers::mark(&mut r.locals, l, n, len);
                }
                for &e in &reads.execs {
                    Readers::mark(&mut r.execs, e, n, len);
                }
            }
            self.readers[at] = Some(r);
        }
        self.readers[at].as_ref().expect("built")
    }

    /// Works out the reads of node `n` of body `b` (table `at`, see [`ReadsTable::node`])
    /// and of the pure nodes it pulls.
    fn fill(&mut self, checked: &Checked, b: &Body, at: usize, n: usize) {
        let mut stack = vec![(n, false)];
        while let Some((m, inputs_done)) = stack.pop() {
            if self.nodes[at][m].is_some() {
                continue;
            }
            let node = &b.nodes[m];
            if !inputs_done {
                stack.push((m, true));
                for a in &node.inputs {
                    if let Src::Node { node: dep, .. } = a.src
                        && b.nodes[dep].pure
                        && self.nodes[at][dep].is_none()
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
                        if let Some(r) = &self.nodes[at][dep] {
                            reads.add(r);
                        }
                    }
                    // An exec node's outputs change when that node runs again.
                    Src::Node { node: dep, .. } => reads.execs.push(dep),
                    Src::Loop { .. } => reads.loop_vars = true,
                    _ => {}
                }
            }
            reads.stateful |= !node.state.is_empty();
            match node.kind {
                NodeKind::Builtin(op) => reads.pose |= reads_pose(op),
                NodeKind::Call(f) => {
                    let callee = self.function(checked, f);
                    reads.globals.extend_from_slice(&callee.globals);
                    reads.pose |= callee.pose;
                    reads.stateful |= callee.stateful;
                }
            }
            reads.normalise();
            self.nodes[at][m] = Some(reads);
        }
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
            reads.stateful |= r.stateful || !b.nodes[n].state.is_empty();
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
    each_step(steps, |s| step_args(s, &mut arg));
}
