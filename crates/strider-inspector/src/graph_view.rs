//! The graph view: one body at a time (the graph's top level or a function, reached by a
//! call path, with a breadcrumb), every node with its pins and links, the exec steps that
//! read values (`Set`, `Branch`, `ForEach`, `For`, `Return`), comment boxes from the file's
//! `editor` section, live pin values and, with profiling, each node's time. Drawn with
//! egui-snarl; the graph file is only read.
//!
//! A node inside a function has one set of slots per call site: the view shows the values
//! of the call path it was opened through. Inside a loop the slot holds the last
//! iteration's value, and the view says so: "(last iteration)" after the value in a pin's
//! tooltip, a line in the node panel.

use crate::layout::{Layout, TOP_LEVEL};
use crate::values::{ValueSource, format_value};
use egui::{Color32, Pos2, Rect, Ui, emath::TSTransform, pos2, vec2};
use egui_snarl::ui::{BackgroundPattern, PinInfo, SnarlPin, SnarlStyle, SnarlViewer, SnarlWidget};
use egui_snarl::{InPin, InPinId, NodeId, OutPin, OutPinId, Snarl};
use std::collections::HashMap;
use std::path::PathBuf;
use strider_graph::{
    Editor, ExprKind, FunctionDecl, Graph, Literal, LiteralKind, LoadedGraph, NodeDecl, Step,
};
use strider_nodes::{ValueType, registry};
use strider_vm::{PinOwner, Program};

/// One level of the breadcrumb: a function opened through a call node.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Crumb {
    /// The function.
    pub function: String,
    /// The call node's index in the caller's body (see `strider_vm::PinSlot::call_path`).
    pub call_index: u32,
    /// The call node's label, for the breadcrumb.
    pub label: String,
}

/// What feeds an input pin.
#[derive(Clone, Debug, PartialEq)]
pub enum PinSource {
    /// Another node's output (or a function input / loop name when no node has that id).
    Link {
        /// Node id (or input / loop name).
        node: String,
        /// Output pin, when written.
        pin: Option<String>,
    },
    /// A variable (graph-level or a function local).
    Var(String),
    /// A literal, as text.
    Literal(String),
    /// Not given: the node's default, as text.
    Default(String),
}

/// A node or exec step of a body.
#[derive(Clone, Debug)]
pub struct GraphNode {
    /// Index among the body's nodes (checker order) for nodes; `None` for steps.
    pub index: Option<u32>,
    /// Node type (`Sin`, a function name) or the step (`Set Time`, `Branch`, ...).
    pub node_type: String,
    /// The node's id, if it has one.
    pub id: Option<String>,
    /// The called function, for call nodes.
    pub calls: Option<String>,
    /// Input pins.
    pub inputs: Vec<(String, PinSource)>,
    /// Output pin names.
    pub outputs: Vec<String>,
    /// Where it is written, `file:line:col`.
    pub location: String,
    /// Whether its values are those of a loop's last iteration: it sits in a `ForEach` or
    /// `For` body, or reads (through its inputs) a loop's element, index or count.
    pub in_loop: bool,
}

impl GraphNode {
    /// The id, or the type for an anonymous node or a step.
    #[must_use]
    pub fn label(&self) -> &str {
        self.id.as_deref().unwrap_or(&self.node_type)
    }
}

/// A body of the document, laid out.
#[derive(Clone, Debug, Default)]
pub struct Body {
    /// Nodes (in checker order) then steps.
    pub nodes: Vec<GraphNode>,
    /// Links: (from node, output, to node, input), indices into `nodes`.
    pub links: Vec<(usize, usize, usize, usize)>,
    /// Canvas position of each node.
    pub positions: Vec<Pos2>,
    /// Comment boxes: title, colour, member nodes.
    pub comments: Vec<(String, Color32, Vec<usize>)>,
}

fn literal_text(l: &Literal) -> String {
    match &l.kind {
        LiteralKind::Bool(b) => b.to_string(),
        LiteralKind::Int(i) => i.to_string(),
        LiteralKind::Float(x) => format!("{x}"),
        LiteralKind::Numbers(n) => format!(
            "({})",
            n.iter()
                .map(|x| format!("{x}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        LiteralKind::Euler(e) => format!("euler({}, {}, {})", e[0], e[1], e[2]),
        LiteralKind::Transform { .. } => "(transform)".to_string(),
        LiteralKind::Bone(b) => format!("bone(\"{b}\")"),
        LiteralKind::NoBone => "None".to_string(),
        LiteralKind::Name(n) => format!("name(\"{n}\")"),
        LiteralKind::Word(w) => w.clone(),
        LiteralKind::List(items) => format!("[{}]", items.len()),
    }
}

fn source_of(expr: &strider_graph::Expr) -> PinSource {
    match &expr.kind {
        ExprKind::Link { source, pin } => PinSource::Link {
            node: source.clone(),
            pin: pin.clone(),
        },
        ExprKind::Var(name) => PinSource::Var(name.clone()),
        ExprKind::Literal(l) => PinSource::Literal(literal_text(l)),
    }
}

/// Finds a function by name in the main graph or its libraries.
#[must_use]
pub fn find_function<'a>(loaded: &'a LoadedGraph, name: &str) -> Option<&'a FunctionDecl> {
    std::iter::once(&loaded.main)
        .chain(&loaded.libraries)
        .flat_map(|g| &g.functions)
        .find(|f| f.name.name == name)
}

fn node_of(loaded: &LoadedGraph, d: &NodeDecl, index: Option<u32>) -> GraphNode {
    let location = loaded.sources.describe(d.loc);
    let given: Vec<(String, PinSource)> = d
        .pins
        .iter()
        .map(|p| (p.name.name.clone(), source_of(&p.value)))
        .collect();
    let (inputs, outputs, calls) = if let Some(spec) = registry().get(&d.kind.name) {
        let o = &spec.overloads[0];
        let mut inputs = Vec::new();
        for pin in &o.inputs {
            match given.iter().find(|(n, _)| n == pin.name) {
                Some((n, s)) => inputs.push((n.clone(), s.clone())),
                None => inputs.push((
                    pin.name.to_string(),
                    PinSource::Default(
                        pin.default
                            .as_ref()
                            .map_or_else(|| "—".to_string(), format_value),
                    ),
                )),
            }
        }
        // Pins written that the first overload does not name (other overloads).
        for (n, s) in &given {
            if !inputs.iter().any(|(m, _)| m == n) {
                inputs.push((n.clone(), s.clone()));
            }
        }
        let outputs = o.outputs.iter().map(|p| p.name.to_string()).collect();
        (inputs, outputs, None)
    } else if let Some(f) = find_function(loaded, &d.kind.name) {
        let inputs = f
            .inputs
            .iter()
            .map(|p| {
                let source = given.iter().find(|(n, _)| *n == p.name.name).map_or_else(
                    || {
                        PinSource::Default(
                            p.default.as_ref().map_or_else(|| "—".into(), literal_text),
                        )
                    },
                    |(_, s)| s.clone(),
                );
                (p.name.name.clone(), source)
            })
            .collect();
        let outputs = f.outputs.iter().map(|p| p.name.name.clone()).collect();
        (inputs, outputs, Some(f.name.name.clone()))
    } else {
        (given, Vec::new(), None)
    };
    GraphNode {
        index,
        node_type: d.kind.name.clone(),
        id: d.id.as_ref().map(|i| i.name.clone()),
        calls,
        inputs,
        outputs,
        location,
        in_loop: false,
    }
}

fn step_node(loaded: &LoadedGraph, step: &Step) -> Option<GraphNode> {
    let (node_type, inputs, loc) = match step {
        Step::Set { var, value, loc } => (
            format!("Set {}", var.name),
            vec![("value".to_string(), source_of(value))],
            *loc,
        ),
        Step::Branch { condition, loc, .. } => (
            "Branch".to_string(),
            vec![("condition".to_string(), source_of(condition))],
            *loc,
        ),
        Step::ForEach {
            items,
            element,
            loc,
            ..
        } => (
            format!("ForEach {}", element.name),
            vec![("items".to_string(), source_of(items))],
            *loc,
        ),
        Step::For {
            count, index, loc, ..
        } => (
            format!("For {}", index.name),
            vec![("count".to_string(), source_of(count))],
            *loc,
        ),
        Step::Return { values, loc } => (
            "Return".to_string(),
            values
                .iter()
                .map(|p| (p.name.name.clone(), source_of(&p.value)))
                .collect(),
            *loc,
        ),
        Step::Run(_) | Step::Node(_) | Step::Sequence(..) => return None,
    };
    Some(GraphNode {
        index: None,
        node_type,
        id: None,
        calls: None,
        inputs,
        outputs: Vec::new(),
        location: loaded.sources.describe(loc),
        in_loop: false,
    })
}

/// What [`walk`] collects besides the nodes.
struct Walk<'a> {
    loaded: &'a LoadedGraph,
    /// Steps that read values, as nodes.
    step_nodes: Vec<GraphNode>,
    /// The names loops give their element, index and count.
    loop_names: Vec<String>,
}

/// Walks exec lists in the checker's order: inline nodes get the next indices; steps
/// that read values become step nodes; `in_loop` marks what sits in a loop body.
fn walk(w: &mut Walk<'_>, steps: &[Step], nodes: &mut Vec<GraphNode>, in_loop: bool) {
    for s in steps {
        if let Some(mut n) = step_node(w.loaded, s) {
            n.in_loop = in_loop;
            w.step_nodes.push(n);
        }
        match s {
            Step::Node(d) => {
                let index = nodes.len() as u32;
                let mut n = node_of(w.loaded, d, Some(index));
                n.in_loop = in_loop;
                nodes.push(n);
            }
            Step::ForEach {
                element,
                index,
                count,
                body,
                ..
            } => {
                w.loop_names.extend(
                    std::iter::once(element)
                        .chain(index)
                        .chain(count)
                        .map(|i| i.name.clone()),
                );
                walk(w, body, nodes, true);
            }
            Step::For { index, body, .. } => {
                w.loop_names.push(index.name.clone());
                walk(w, body, nodes, true);
            }
            Step::Branch {
                then, otherwise, ..
            } => {
                walk(w, then, nodes, in_loop);
                walk(w, otherwise, nodes, in_loop);
            }
            Step::Sequence(blocks, _) => {
                for b in blocks {
                    walk(w, b, nodes, in_loop);
                }
            }
            Step::Set { .. } | Step::Run(_) | Step::Return { .. } => {}
        }
    }
}

/// Marks every node that reads a loop's name, or a node so marked, through its inputs.
fn mark_loop_readers(nodes: &mut [GraphNode], loop_names: &[String]) {
    let ids: Vec<Option<String>> = nodes.iter().map(|n| n.id.clone()).collect();
    loop {
        let mut changed = false;
        for i in 0..nodes.len() {
            if nodes[i].in_loop {
                continue;
            }
            let reads_loop = nodes[i].inputs.iter().any(|(_, source)| match source {
                PinSource::Link { node, .. } => {
                    match ids.iter().position(|id| id.as_ref() == Some(node)) {
                        Some(from) => nodes[from].in_loop,
                        None => loop_names.contains(node),
                    }
                }
                _ => false,
            });
            if reads_loop {
                nodes[i].in_loop = true;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
}

/// The body of `function` (`None`: the graph's top level) with its links and layout.
#[must_use]
pub fn build_body(loaded: &LoadedGraph, function: Option<&str>) -> Body {
    let main: &Graph = &loaded.main;
    let (decls, lists): (&[NodeDecl], Vec<&[Step]>) =
        match function.and_then(|f| find_function(loaded, f)) {
            Some(f) => (&f.nodes, vec![&f.exec]),
            None => (
                &main.nodes,
                [
                    strider_graph::EventKind::Construction,
                    strider_graph::EventKind::Forward,
                ]
                .iter()
                .flat_map(|k| main.events.iter().filter(move |e| e.kind == *k))
                .map(|e| e.steps.as_slice())
                .collect(),
            ),
        };
    let mut nodes: Vec<GraphNode> = decls
        .iter()
        .enumerate()
        .map(|(i, d)| node_of(loaded, d, Some(i as u32)))
        .collect();
    let mut w = Walk {
        loaded,
        step_nodes: Vec::new(),
        loop_names: Vec::new(),
    };
    for list in lists {
        walk(&mut w, list, &mut nodes, false);
    }
    nodes.extend(w.step_nodes);
    mark_loop_readers(&mut nodes, &w.loop_names);

    let mut links = Vec::new();
    for (to, n) in nodes.iter().enumerate() {
        for (input, (_, source)) in n.inputs.iter().enumerate() {
            if let PinSource::Link { node, pin } = source
                && let Some(from) = nodes.iter().position(|m| m.id.as_deref() == Some(node))
            {
                let output = match pin {
                    Some(p) => nodes[from].outputs.iter().position(|o| o == p),
                    None => (!nodes[from].outputs.is_empty()).then_some(0),
                };
                if let Some(output) = output {
                    links.push((from, output, to, input));
                }
            }
        }
    }
    let positions = layout(&nodes, &links, &main.editor);
    let comments = main
        .editor
        .comments
        .iter()
        .filter_map(|c| {
            let members: Vec<usize> = c
                .nodes
                .iter()
                .filter_map(|id| nodes.iter().position(|n| n.id.as_deref() == Some(&id.name)))
                .collect();
            (!members.is_empty()).then(|| {
                let [r, g, b] = c.color.map(|x| (x.clamp(0.0, 1.0) * 255.0) as u8);
                (c.title.clone(), Color32::from_rgb(r, g, b), members)
            })
        })
        .collect();
    Body {
        nodes,
        links,
        positions,
        comments,
    }
}

/// `value` followed by "(last iteration)" when `node` is in a loop.
fn last_iteration(node: &GraphNode, value: String) -> String {
    if node.in_loop {
        format!("{value} (last iteration)")
    } else {
        value
    }
}

/// Node `i`'s name in a layout file: its id, else `label#n` for the n-th node of the body
/// with that label and no id.
fn layout_key(nodes: &[GraphNode], i: usize) -> String {
    let n = &nodes[i];
    match &n.id {
        Some(id) => id.clone(),
        None => {
            let k = nodes[..i]
                .iter()
                .filter(|m| m.id.is_none() && m.label() == n.label())
                .count();
            format!("{}#{k}", n.label())
        }
    }
}

fn path_text(path: &Option<PathBuf>) -> String {
    path.as_ref()
        .map_or_else(String::new, |p| p.display().to_string())
}

/// Rough node height for the layout (header and one row per pin).
fn node_height(n: &GraphNode) -> f32 {
    40.0 + 22.0 * n.inputs.len().max(n.outputs.len()) as f32
}

/// Positions from the editor section where given; otherwise layered: each node one column
/// right of the deepest node feeding it, stacked in its column.
fn layout(
    nodes: &[GraphNode],
    links: &[(usize, usize, usize, usize)],
    editor: &Editor,
) -> Vec<Pos2> {
    let mut depth = vec![0usize; nodes.len()];
    for _ in 0..nodes.len().min(64) {
        let mut changed = false;
        for &(from, _, to, _) in links {
            if depth[to] < depth[from] + 1 && depth[from] + 1 < nodes.len() + 1 {
                depth[to] = depth[from] + 1;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    // Columns taller than COLUMN_HEIGHT wrap into several side by side.
    let mut columns: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, d) in depth.iter().enumerate() {
        columns.entry(*d).or_default().push(i);
    }
    let mut order: Vec<usize> = columns.keys().copied().collect();
    order.sort_unstable();
    let mut positions = vec![Pos2::ZERO; nodes.len()];
    let mut x = 0.0;
    for d in order {
        let (mut y, mut wraps) = (0.0, 0);
        for &i in &columns[&d] {
            if y > 0.0 && y + node_height(&nodes[i]) > COLUMN_HEIGHT {
                y = 0.0;
                wraps += 1;
            }
            positions[i] = pos2(x + wraps as f32 * COLUMN_WIDTH, y);
            y += node_height(&nodes[i]) + 30.0;
        }
        x += (wraps + 1) as f32 * COLUMN_WIDTH;
    }
    for (i, n) in nodes.iter().enumerate() {
        if let Some(id) = &n.id
            && let Some((_, [x, y])) = editor.positions.iter().find(|(k, _)| &k.name == id)
        {
            positions[i] = pos2(*x as f32, *y as f32);
        }
    }
    positions
}

/// Width of a layout column and the height at which a column wraps, canvas units.
const COLUMN_WIDTH: f32 = 300.0;
const COLUMN_HEIGHT: f32 = 900.0;

/// The smallest zoom "Fit" uses (below it node text is unreadable).
const MIN_FIT_SCALE: f32 = 0.45;

/// Where one pin's value lives for the body shown: `(type, slot)`.
type SlotOf = (ValueType, u32);

/// State of the graph view.
pub struct GraphViewState {
    /// Functions opened, from the top level down.
    pub path: Vec<Crumb>,
    snarl: Snarl<GraphNode>,
    body: Body,
    built: Option<(u32, Vec<Crumb>)>,
    outputs: HashMap<(u32, String), SlotOf>,
    locals: HashMap<String, SlotOf>,
    /// The selected node (index into the body's nodes).
    pub selected: Option<usize>,
    /// Colour nodes by time and print µs (profiling builds).
    pub show_profile: bool,
    rects: HashMap<NodeId, Rect>,
    fit: bool,
    view_rect: Rect,
    fitted_rect: Rect,
    open: Option<Crumb>,
    id: egui::Id,
    /// Where the user dragged nodes, every body (see [`crate::layout`]).
    pub layout: Layout,
    /// The layout file ("Save layout" and leaving the inspector write it).
    pub layout_path: Option<PathBuf>,
    /// Whether nodes moved since the layout was loaded or saved.
    pub layout_dirty: bool,
    /// The last layout load or save outcome: (ok, message).
    pub layout_message: Option<(bool, String)>,
}

impl Default for GraphViewState {
    fn default() -> Self {
        Self {
            path: Vec::new(),
            snarl: Snarl::new(),
            body: Body::default(),
            built: None,
            outputs: HashMap::new(),
            locals: HashMap::new(),
            selected: None,
            show_profile: false,
            rects: HashMap::new(),
            fit: true,
            view_rect: Rect::NOTHING,
            fitted_rect: Rect::NOTHING,
            open: None,
            id: egui::Id::new("strider-graph-view"),
            layout: Layout::default(),
            layout_path: None,
            layout_dirty: false,
            layout_message: None,
        }
    }
}

impl GraphViewState {
    /// The call path of the body shown.
    #[must_use]
    pub fn call_path(&self) -> Vec<u32> {
        self.path.iter().map(|c| c.call_index).collect()
    }

    /// The body shown.
    #[must_use]
    pub fn body(&self) -> &Body {
        &self.body
    }

    /// Opens `function` through call node `call_index` of the body shown.
    pub fn open_function(&mut self, function: &str, call_index: u32, label: &str) {
        self.path.push(Crumb {
            function: function.to_string(),
            call_index,
            label: label.to_string(),
        });
        self.selected = None;
    }

    /// Opens `function` through the first call path that reaches it (a function reached
    /// by no call path opens without values). Returns whether one was found.
    pub fn open_function_anywhere(
        &mut self,
        program: &Program,
        loaded: &LoadedGraph,
        function: &str,
    ) -> bool {
        let Some(entry) = program
            .pin_slots()
            .iter()
            .find(|p| p.function.as_deref() == Some(function))
        else {
            return false;
        };
        self.path.clear();
        let mut caller: Option<String> = None;
        for &index in &entry.call_path {
            let body = build_body(loaded, caller.as_deref());
            let Some(node) = body.nodes.iter().find(|n| n.index == Some(index)) else {
                return false;
            };
            let Some(f) = node.calls.clone() else {
                return false;
            };
            self.path.push(Crumb {
                function: f.clone(),
                call_index: index,
                label: node.label().to_string(),
            });
            caller = Some(f);
        }
        self.selected = None;
        true
    }

    /// Selects the node whose label (id, or type for anonymous nodes) is `label`.
    pub fn select(&mut self, label: &str) -> bool {
        self.selected = self.body.nodes.iter().position(|n| n.label() == label);
        self.selected.is_some()
    }

    /// Reads the layout file of `graph` (`<stem>.layout.ron`, see [`crate::layout`]). On
    /// error the message says why and nothing will be written over that file (there is
    /// no "Save layout" until it is fixed and the inspector opened again).
    pub fn load_layout(&mut self, graph: &std::path::Path) {
        let path = Layout::path_for(graph);
        match Layout::load(&path) {
            Ok(layout) => {
                self.layout = layout;
                self.layout_message = None;
                self.layout_path = Some(path);
            }
            Err(e) => {
                self.layout_message = Some((false, format!("{e}; the layout is not saved")));
                self.layout_path = None;
            }
        }
        self.layout_dirty = false;
        self.built = None;
    }

    /// Writes the layout file when nodes were moved since the last save (and a layout file
    /// path is set).
    ///
    /// # Errors
    /// When the file cannot be written.
    pub fn save_layout(&mut self) -> Result<(), String> {
        let Some(path) = &self.layout_path else {
            return Ok(());
        };
        self.layout.save(path)?;
        self.layout_dirty = false;
        Ok(())
    }

    /// The body shown's name in the layout file.
    fn layout_body(&self) -> &str {
        self.path.last().map_or(TOP_LEVEL, |c| c.function.as_str())
    }

    /// Keeps in the layout the position of every node the user moved on the canvas.
    fn note_moves(&mut self) {
        let mut moved = Vec::new();
        for (id, pos, _) in self.snarl.nodes_pos_ids() {
            if self.body.positions.get(id.0).is_some_and(|p| *p != pos) {
                moved.push((id.0, pos));
            }
        }
        for (i, pos) in moved {
            self.body.positions[i] = pos;
            let key = layout_key(&self.body.nodes, i);
            let body = self.layout_body().to_string();
            self.layout.set(&body, &key, pos);
            self.layout_dirty = true;
        }
    }

    /// Asks the view to fit every node on its next frame.
    pub fn request_fit(&mut self) {
        self.fit = true;
    }

    /// Rebuilds the body when the program or the path changed.
    pub fn sync(&mut self, loaded: &LoadedGraph, program: &Program, generation: u32) {
        let key = (generation, self.path.clone());
        if self.built.as_ref() == Some(&key) {
            return;
        }
        let same_path = self.built.as_ref().is_some_and(|(_, p)| *p == self.path);
        self.built = Some(key);
        let function = self.path.last().map(|c| c.function.clone());
        self.body = build_body(loaded, function.as_deref());
        let body = self.layout_body().to_string();
        for i in 0..self.body.nodes.len() {
            if let Some(p) = self
                .layout
                .position(&body, &layout_key(&self.body.nodes, i))
            {
                self.body.positions[i] = p;
            }
        }
        self.snarl = Snarl::new();
        for (n, p) in self.body.nodes.iter().zip(&self.body.positions) {
            self.snarl.insert_node(*p, n.clone());
        }
        for &(from, output, to, input) in &self.body.links {
            self.snarl.connect(
                OutPinId {
                    node: NodeId(from),
                    output,
                },
                InPinId {
                    node: NodeId(to),
                    input,
                },
            );
        }
        let path = self.call_path();
        self.outputs.clear();
        self.locals.clear();
        for p in program.pin_slots().iter().filter(|p| p.call_path == path) {
            match p.owner {
                PinOwner::NodeOutput(n) => {
                    self.outputs.insert((n, p.pin.to_string()), (p.ty, p.slot));
                }
                PinOwner::FunctionInput | PinOwner::Local => {
                    self.locals.insert(p.pin.to_string(), (p.ty, p.slot));
                }
            }
        }
        self.rects.clear();
        if !same_path {
            self.fit = true;
            self.selected = None;
        }
    }

    /// The slot of output `pin` of body node `n`.
    #[must_use]
    pub fn output_slot(&self, n: usize, pin: &str) -> Option<SlotOf> {
        let index = self.body.nodes.get(n)?.index?;
        self.outputs.get(&(index, pin.to_string())).copied()
    }

    /// The slot an input pin reads, when it reads a node, a function input or a variable.
    #[must_use]
    pub fn input_slot(&self, program: &Program, source: &PinSource) -> Option<SlotOf> {
        match source {
            PinSource::Link { node, pin } => {
                if let Some(from) = self
                    .body
                    .nodes
                    .iter()
                    .position(|m| m.id.as_deref() == Some(node))
                {
                    let pin = match pin {
                        Some(p) => p.clone(),
                        None => self.body.nodes[from].outputs.first()?.clone(),
                    };
                    self.output_slot(from, &pin)
                } else {
                    self.locals.get(node).copied()
                }
            }
            PinSource::Var(name) => self.locals.get(name).copied().or_else(|| {
                program
                    .variable_id(name)
                    .map(|id| (program.variable(id).ty, program.variable(id).slot))
            }),
            PinSource::Literal(_) | PinSource::Default(_) => None,
        }
    }

    /// Text for an input pin's current value.
    #[must_use]
    pub fn input_text(
        &self,
        program: &Program,
        source: &PinSource,
        values: &ValueSource<'_>,
    ) -> String {
        match source {
            PinSource::Literal(t) => t.clone(),
            PinSource::Default(t) => format!("{t} (default)"),
            _ => self
                .input_slot(program, source)
                .and_then(|(ty, slot)| values.read(ty, slot))
                .map_or_else(|| "—".to_string(), |v| format_value(&v)),
        }
    }

    /// Text for an output pin's current value.
    #[must_use]
    pub fn output_text(&self, n: usize, pin: &str, values: &ValueSource<'_>) -> String {
        self.output_slot(n, pin)
            .and_then(|(ty, slot)| values.read(ty, slot))
            .map_or_else(|| "—".to_string(), |v| format_value(&v))
    }

    /// Shows the breadcrumb, the toolbar and the node canvas. `profile` maps a node's
    /// location to its mean time per frame, µs.
    pub fn show(
        &mut self,
        ui: &mut Ui,
        program: &Program,
        loaded: &LoadedGraph,
        values: &ValueSource<'_>,
        profile: Option<&HashMap<String, f64>>,
    ) {
        ui.horizontal(|ui| {
            if ui.link(program.name()).clicked() {
                self.path.clear();
            }
            let mut cut = None;
            for (i, c) in self.path.iter().enumerate() {
                ui.label(">");
                if ui
                    .link(&c.function)
                    .on_hover_text(format!("called by `{}`", c.label))
                    .clicked()
                {
                    cut = Some(i + 1);
                }
            }
            if let Some(n) = cut {
                self.path.truncate(n);
            }
            ui.separator();
            if ui.button("Fit").clicked() {
                self.fit = true;
            }
            if let Some(path) = &self.layout_path {
                let hover = format!(
                    "write where the nodes are to {} (the graph file is never rewritten); \
                     leaving the inspector writes it too",
                    path.display()
                );
                let label = if self.layout_dirty {
                    "Save layout*"
                } else {
                    "Save layout"
                };
                if ui.button(label).on_hover_text(hover).clicked() {
                    self.layout_message = Some(match self.save_layout() {
                        Ok(()) => (true, format!("wrote {}", path_text(&self.layout_path))),
                        Err(e) => (false, e),
                    });
                }
            }
            if let Some((ok, m)) = &self.layout_message {
                let color = if *ok {
                    Color32::from_rgb(120, 220, 120)
                } else {
                    Color32::from_rgb(255, 140, 110)
                };
                ui.label(egui::RichText::new(m).color(color));
            }
            egui::ComboBox::from_id_salt("open-function")
                .selected_text("Open function…")
                .show_ui(ui, |ui| {
                    let names: Vec<String> = std::iter::once(&loaded.main)
                        .chain(&loaded.libraries)
                        .flat_map(|g| &g.functions)
                        .map(|f| f.name.name.clone())
                        .collect();
                    for name in names {
                        if ui.selectable_label(false, &name).clicked() {
                            self.open_function_anywhere(program, loaded, &name);
                        }
                    }
                });
            ui.add_enabled(
                profile.is_some(),
                egui::Checkbox::new(&mut self.show_profile, "Time per node"),
            )
            .on_disabled_hover_text(
                "per-node times need a build with the `profile` feature \
                 (cargo run --release --features profile)",
            );
        });
        let rect = ui.available_rect_before_wrap();
        self.view_rect = rect;
        // The window or the panel moved or changed size: fit again.
        if (rect.min - self.fitted_rect.min).length() + (rect.max - self.fitted_rect.max).length()
            > 1.0
        {
            self.fitted_rect = rect;
            self.fit = true;
        }
        let profile = if self.show_profile { profile } else { None };
        let max_us = profile
            .map(|p| p.values().copied().fold(0.0, f64::max))
            .unwrap_or(0.0);
        let mut viewer = Viewer {
            state_outputs: &self.outputs,
            body: &self.body,
            locals: &self.locals,
            program,
            values,
            profile,
            max_us,
            rects: &mut self.rects,
            open: &mut self.open,
            select: &mut self.selected,
            fit: &mut self.fit,
            view_rect: rect,
        };
        let mut style = SnarlStyle::new();
        style.bg_pattern = Some(BackgroundPattern::grid(vec2(50.0, 50.0), 0.0));
        style.collapsible = Some(false);
        SnarlWidget::new()
            .id(self.id)
            .style(style)
            .show(&mut self.snarl, &mut viewer, ui);
        self.note_moves();
        // Shift-click selects in egui-snarl; a click on a node's title selects too.
        if let Some(first) = egui_snarl::ui::get_selected_nodes(self.id, ui.ctx()).first() {
            self.selected = Some(first.0);
        }
        if let Some(c) = self.open.take() {
            self.path.push(c);
            self.selected = None;
        }
    }

    /// The selected node's pins with their values, and a button per plottable pin. Returns
    /// the pins to plot: `(label, type, slot)`.
    pub fn show_selected(
        &self,
        ui: &mut Ui,
        program: &Program,
        values: &ValueSource<'_>,
    ) -> Option<(String, ValueType, u32)> {
        let mut plot = None;
        let Some(n) = self
            .selected
            .and_then(|i| self.body.nodes.get(i).map(|n| (i, n)))
        else {
            ui.label("Select a node to see its pins.");
            return None;
        };
        let (i, node) = n;
        ui.heading(node.label());
        ui.label(format!("{} — {}", node.node_type, node.location));
        if node.index.is_none() {
            ui.label("exec step");
        }
        if node.in_loop {
            ui.label("in a loop: the values of its last iteration");
        }
        ui.separator();
        egui::Grid::new("selected-pins")
            .striped(true)
            .show(ui, |ui| {
                for (name, source) in &node.inputs {
                    ui.label(format!("in  {name}"));
                    let text = self.input_text(program, source, values);
                    let from = match source {
                        PinSource::Link { node, pin } => match pin {
                            Some(p) => format!("← {node}.{p}"),
                            None => format!("← {node}"),
                        },
                        PinSource::Var(v) => format!("← var(\"{v}\")"),
                        _ => String::new(),
                    };
                    ui.label(text).on_hover_text(from);
                    match self.input_slot(program, source) {
                        Some((ty, slot)) if plottable(ty) => {
                            if ui.small_button("plot").clicked() {
                                plot = Some((format!("{}.{name}", node.label()), ty, slot));
                            }
                        }
                        _ => {
                            ui.label("");
                        }
                    }
                    ui.end_row();
                }
                for name in &node.outputs {
                    ui.label(format!("out {name}"));
                    ui.label(self.output_text(i, name, values));
                    match self.output_slot(i, name) {
                        Some((ty, slot)) if plottable(ty) => {
                            if ui.small_button("plot").clicked() {
                                plot = Some((format!("{}.{name}", node.label()), ty, slot));
                            }
                        }
                        _ => {
                            ui.label("");
                        }
                    }
                    ui.end_row();
                }
            });
        plot
    }
}

/// Whether plots can show a value of type `ty` (numbers, bools, vector components).
#[must_use]
pub fn plottable(ty: ValueType) -> bool {
    matches!(
        ty,
        ValueType::Float | ValueType::Int | ValueType::Bool | ValueType::Vec3
    )
}

struct Viewer<'a> {
    state_outputs: &'a HashMap<(u32, String), SlotOf>,
    body: &'a Body,
    locals: &'a HashMap<String, SlotOf>,
    program: &'a Program,
    values: &'a ValueSource<'a>,
    profile: Option<&'a HashMap<String, f64>>,
    max_us: f64,
    rects: &'a mut HashMap<NodeId, Rect>,
    open: &'a mut Option<Crumb>,
    select: &'a mut Option<usize>,
    fit: &'a mut bool,
    view_rect: Rect,
}

impl Viewer<'_> {
    fn value_text(&self, slot: Option<SlotOf>) -> Option<String> {
        slot.and_then(|(ty, s)| self.values.read(ty, s))
            .map(|v| format_value(&v))
    }

    fn input_slot(&self, source: &PinSource) -> Option<SlotOf> {
        match source {
            PinSource::Link { node, pin } => {
                match self
                    .body
                    .nodes
                    .iter()
                    .position(|m| m.id.as_deref() == Some(node))
                {
                    Some(from) => {
                        let n = &self.body.nodes[from];
                        let pin = pin.clone().or_else(|| n.outputs.first().cloned())?;
                        self.state_outputs.get(&(n.index?, pin)).copied()
                    }
                    None => self.locals.get(node).copied(),
                }
            }
            PinSource::Var(name) => self.locals.get(name).copied().or_else(|| {
                self.program
                    .variable_id(name)
                    .map(|id| (self.program.variable(id).ty, self.program.variable(id).slot))
            }),
            _ => None,
        }
    }
}

fn heat(fraction: f64) -> Color32 {
    let t = fraction.clamp(0.0, 1.0) as f32;
    let lerp = |a: f32, b: f32| (a + (b - a) * t) as u8;
    Color32::from_rgb(lerp(40.0, 200.0), lerp(70.0, 50.0), lerp(60.0, 30.0))
}

impl SnarlViewer<GraphNode> for Viewer<'_> {
    fn title(&mut self, node: &GraphNode) -> String {
        match &node.id {
            Some(id) => format!("{id}: {}", node.node_type),
            None => node.node_type.clone(),
        }
    }

    fn show_header(
        &mut self,
        node: NodeId,
        _inputs: &[InPin],
        _outputs: &[OutPin],
        ui: &mut Ui,
        snarl: &mut Snarl<GraphNode>,
    ) {
        let n = &snarl[node];
        let title = self.title(n);
        let label =
            egui::Label::new(egui::RichText::new(title).strong()).sense(egui::Sense::click());
        if ui
            .add(label)
            .on_hover_text(format!("{} — click to list its pins", n.location))
            .clicked()
        {
            *self.select = Some(node.0);
        }
        if let Some(us) = self.profile.and_then(|p| p.get(&n.location)) {
            ui.label(egui::RichText::new(format!("{us:.2} µs")).monospace());
        }
        if let (Some(f), Some(index)) = (&n.calls, n.index)
            && ui
                .small_button("open")
                .on_hover_text(format!("open {f}"))
                .clicked()
        {
            *self.open = Some(Crumb {
                function: f.clone(),
                call_index: index,
                label: n.label().to_string(),
            });
        }
    }

    fn header_frame(
        &mut self,
        default: egui::Frame,
        node: NodeId,
        _inputs: &[InPin],
        _outputs: &[OutPin],
        snarl: &Snarl<GraphNode>,
    ) -> egui::Frame {
        let n = &snarl[node];
        if *self.select == Some(node.0) {
            return default.fill(Color32::from_rgb(150, 110, 30));
        }
        match self.profile.and_then(|p| p.get(&n.location)) {
            Some(&us) if self.max_us > 0.0 => default.fill(heat(us / self.max_us)),
            _ if n.index.is_none() => default.fill(Color32::from_rgb(60, 60, 90)),
            _ if n.calls.is_some() => default.fill(Color32::from_rgb(40, 80, 110)),
            _ => default,
        }
    }

    fn inputs(&mut self, node: &GraphNode) -> usize {
        node.inputs.len()
    }

    fn outputs(&mut self, node: &GraphNode) -> usize {
        node.outputs.len()
    }

    fn show_input(
        &mut self,
        pin: &InPin,
        ui: &mut Ui,
        snarl: &mut Snarl<GraphNode>,
    ) -> impl SnarlPin + 'static {
        let n = &snarl[pin.id.node];
        let (name, source) = &n.inputs[pin.id.input];
        let slot = self.input_slot(source);
        let label = match source {
            PinSource::Literal(t) => format!("{name} = {t}"),
            PinSource::Var(v) => format!("{name} ← {v}"),
            PinSource::Link { node, .. } if pin.remotes.is_empty() => format!("{name} ← {node}"),
            _ => name.clone(),
        };
        // The value is formatted only while the pin is hovered.
        let response = ui.label(label);
        if response.hovered() {
            let value = match source {
                PinSource::Literal(t) => Some(t.clone()),
                PinSource::Default(t) => Some(format!("{t} (default)")),
                _ => self.value_text(slot).map(|v| last_iteration(n, v)),
            };
            response.on_hover_text(value.unwrap_or_else(|| "—".to_string()));
        }
        let mut info = PinInfo::circle();
        info.fill = Some(match source {
            PinSource::Link { .. } => Color32::from_rgb(120, 200, 255),
            PinSource::Var(_) => Color32::from_rgb(120, 230, 140),
            _ => Color32::GRAY,
        });
        info
    }

    fn show_output(
        &mut self,
        pin: &OutPin,
        ui: &mut Ui,
        snarl: &mut Snarl<GraphNode>,
    ) -> impl SnarlPin + 'static {
        let n = &snarl[pin.id.node];
        let name = &n.outputs[pin.id.output];
        let slot = n
            .index
            .and_then(|i| self.state_outputs.get(&(i, name.clone())).copied());
        let response = ui.label(name);
        if response.hovered() {
            let value = self.value_text(slot).map(|v| last_iteration(n, v));
            response.on_hover_text(value.unwrap_or_else(|| "—".to_string()));
        }
        let mut info = PinInfo::circle();
        info.fill = Some(Color32::from_rgb(255, 200, 120));
        info
    }

    fn final_node_rect(
        &mut self,
        node: NodeId,
        rect: Rect,
        _ui: &mut Ui,
        _snarl: &mut Snarl<GraphNode>,
    ) {
        self.rects.insert(node, rect);
    }

    fn current_transform(&mut self, to_global: &mut TSTransform, snarl: &mut Snarl<GraphNode>) {
        if !*self.fit || !self.view_rect.is_positive() {
            return;
        }
        // Canvas positions and estimated sizes (the drawn rects are not needed, so the
        // first frame fits too).
        let mut bounds = Rect::NOTHING;
        for (id, n) in snarl.node_ids() {
            let p = self.body.positions.get(id.0).copied().unwrap_or(Pos2::ZERO);
            bounds = bounds.union(Rect::from_min_size(p, vec2(240.0, node_height(n))));
        }
        if !bounds.is_positive() {
            *self.fit = false;
            return;
        }
        let bounds = bounds.expand(40.0);
        let fit = (self.view_rect.width() / bounds.width())
            .min(self.view_rect.height() / bounds.height());
        // Below MIN_FIT_SCALE text is unreadable: show the graph's start (top left) at that
        // scale instead; pan and zoom reach the rest.
        let scale = fit.clamp(MIN_FIT_SCALE, 1.0);
        let anchor = if fit < MIN_FIT_SCALE {
            self.view_rect.min.to_vec2() - bounds.min.to_vec2() * scale
        } else {
            self.view_rect.center().to_vec2() - bounds.center().to_vec2() * scale
        };
        *to_global = TSTransform::new(anchor, scale);
        *self.fit = false;
    }

    fn draw_background(
        &mut self,
        background: Option<&BackgroundPattern>,
        viewport: &Rect,
        snarl_style: &SnarlStyle,
        style: &egui::Style,
        painter: &egui::Painter,
        _snarl: &Snarl<GraphNode>,
    ) {
        if let Some(b) = background {
            b.draw(viewport, snarl_style, style, painter);
        }
        for (title, color, members) in &self.body.comments {
            let mut r = Rect::NOTHING;
            for m in members {
                if let Some(rect) = self.rects.get(&NodeId(*m)) {
                    r = r.union(*rect);
                }
            }
            if !r.is_positive() {
                continue;
            }
            let r = r.expand2(vec2(20.0, 20.0)).with_min_y(r.min.y - 44.0);
            painter.rect_filled(r, 6.0, color.gamma_multiply(0.35));
            painter.text(
                r.min + vec2(10.0, 6.0),
                egui::Align2::LEFT_TOP,
                title,
                egui::FontId::proportional(16.0),
                Color32::WHITE,
            );
        }
    }
}
