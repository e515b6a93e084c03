//! The editable form of a graph: what the file says, with where it says it.
//!
//! See `docs/format.md` for the syntax these types come from.

use crate::diagnostic::{FileId, Loc};
use strider_nodes::ValueType;

/// A name written in a file, with its location.
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    /// The text.
    pub name: String,
    /// Where it is written.
    pub loc: Loc,
}

/// A graph file (the main graph or an imported library).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Graph {
    /// The file it came from.
    pub file: FileId,
    /// Format version (`version:`).
    pub version: u32,
    /// The graph's name.
    pub name: String,
    /// Library files, as written (relative to this file's folder).
    pub imports: Vec<Ident>,
    /// Variables, in file order.
    pub variables: Vec<VariableDecl>,
    /// Functions, in file order.
    pub functions: Vec<FunctionDecl>,
    /// Graph-level nodes, in file order.
    pub nodes: Vec<NodeDecl>,
    /// Events (`construction`, `forward`).
    pub events: Vec<EventDecl>,
    /// Layout for editors; never needed to run.
    pub editor: Editor,
}

/// A typed, persistent variable (graph-level) or a function-local variable.
#[derive(Clone, Debug, PartialEq)]
pub struct VariableDecl {
    /// Its name.
    pub name: Ident,
    /// Its type.
    pub ty: ValueType,
    /// Where the type is written.
    pub ty_loc: Loc,
    /// Its initial value; the type's zero when absent.
    pub default: Option<Literal>,
    /// Set when a host or the inspector may change it.
    pub tunable: Option<Tunable>,
    /// The whole declaration.
    pub loc: Loc,
}

/// The range of a tunable variable (for sliders); either bound may be open.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Tunable {
    /// Smallest sensible value.
    pub min: Option<f64>,
    /// Largest sensible value.
    pub max: Option<f64>,
}

/// A function input or output.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// Its name.
    pub name: Ident,
    /// Its type.
    pub ty: ValueType,
    /// For inputs: the value used when a call leaves it out (else the input is required).
    pub default: Option<Literal>,
}

/// A named subgraph with typed inputs and outputs, called like a node.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionDecl {
    /// Its name, as calls write it.
    pub name: Ident,
    /// Inputs, in order.
    pub inputs: Vec<Param>,
    /// Outputs, in order.
    pub outputs: Vec<Param>,
    /// Local variables, reset to their defaults at every call.
    pub locals: Vec<VariableDecl>,
    /// Nodes of the body.
    pub nodes: Vec<NodeDecl>,
    /// The body's exec list.
    pub exec: Vec<Step>,
    /// The whole declaration.
    pub loc: Loc,
}

/// A node: an id (optional for inline exec nodes), a type (built-in node or function) and
/// its input pins.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeDecl {
    /// The id links refer to; `None` for an anonymous exec node.
    pub id: Option<Ident>,
    /// Node type or function name.
    pub kind: Ident,
    /// Inputs given, in file order.
    pub pins: Vec<PinArg>,
    /// The whole node.
    pub loc: Loc,
}

impl NodeDecl {
    /// The id, or the type name for an anonymous node (for messages).
    #[must_use]
    pub fn label(&self) -> &str {
        self.id.as_ref().map_or(&self.kind.name, |i| &i.name)
    }
}

/// An input pin given a value.
#[derive(Clone, Debug, PartialEq)]
pub struct PinArg {
    /// The pin's name.
    pub name: Ident,
    /// Its value.
    pub value: Expr,
}

/// What feeds an input pin.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// Link, variable or literal.
    pub kind: ExprKind,
    /// Where it is written.
    pub loc: Loc,
}

/// What feeds an input pin.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// `"node"` or `"node.pin"`: another node's output (or a function input, or a loop's
    /// element/index/count name).
    Link {
        /// The node (or input, or loop name).
        source: String,
        /// The output pin, when written.
        pin: Option<String>,
    },
    /// `var("Name")`: a variable's current value.
    Var(String),
    /// A constant.
    Literal(Literal),
}

/// A constant written in a file; typed by the pin or variable it feeds.
#[derive(Clone, Debug, PartialEq)]
pub struct Literal {
    /// Its form.
    pub kind: LiteralKind,
    /// Where it is written.
    pub loc: Loc,
}

/// A constant's form as written.
#[derive(Clone, Debug, PartialEq)]
pub enum LiteralKind {
    /// `true` / `false`.
    Bool(bool),
    /// `3`, `-1`.
    Int(i64),
    /// `1.5`, `1e3`.
    Float(f64),
    /// `(x, y, z)` (a vector) or `(x, y, z, w)` (a quaternion).
    Numbers(Vec<f64>),
    /// `euler(x, y, z)`, degrees, default order.
    Euler([f64; 3]),
    /// `(translation: .., rotation: .., scale: ..)`, each optional.
    Transform {
        /// Translation, cm.
        translation: Option<Box<Literal>>,
        /// Rotation (quaternion or euler).
        rotation: Option<Box<Literal>>,
        /// Scale.
        scale: Option<Box<Literal>>,
    },
    /// `bone("name")`.
    Bone(String),
    /// `None`: no bone.
    NoBone,
    /// `name("text")`.
    Name(String),
    /// A bare word, for pins with named choices (`Global`, `ZYX`).
    Word(String),
    /// `[a, b, c]`.
    List(Vec<Literal>),
}

/// One step of an exec list.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// `Set("Var", value)`: write a variable.
    Set {
        /// The variable.
        var: Ident,
        /// The new value.
        value: Expr,
        /// The whole step.
        loc: Loc,
    },
    /// `Run("id")`: execute a mutating node declared in `nodes`.
    Run(Ident),
    /// An inline node (mutating node or function call), e.g. `SetTransform(...)`.
    Node(NodeDecl),
    /// `Branch(condition: .., then: [..], else: [..])`.
    Branch {
        /// The condition.
        condition: Expr,
        /// Steps when true.
        then: Vec<Step>,
        /// Steps when false.
        otherwise: Vec<Step>,
        /// The whole step.
        loc: Loc,
    },
    /// `ForEach(items: .., element: "e", index: "i", count: "n", body: [..])`.
    ForEach {
        /// The array.
        items: Expr,
        /// Name of the element inside the body.
        element: Ident,
        /// Name of the index inside the body.
        index: Option<Ident>,
        /// Name of the element count inside the body.
        count: Option<Ident>,
        /// The body.
        body: Vec<Step>,
        /// The whole step.
        loc: Loc,
    },
    /// `For(count: .., index: "i", body: [..])`: body runs `count` times, index 0..count.
    For {
        /// Number of iterations.
        count: Expr,
        /// Name of the index inside the body.
        index: Ident,
        /// The body.
        body: Vec<Step>,
        /// The whole step.
        loc: Loc,
    },
    /// `Sequence([..], [..])`: the blocks one after the other.
    Sequence(Vec<Vec<Step>>, Loc),
    /// `Return` or `Return(output: value, ..)`: leave the function (or event).
    Return {
        /// Outputs set on the way out.
        values: Vec<PinArg>,
        /// The whole step.
        loc: Loc,
    },
}

/// Which event an exec list runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// At instantiation and whenever the skeleton changes.
    Construction,
    /// Every frame.
    Forward,
}

/// An event's exec list.
#[derive(Clone, Debug, PartialEq)]
pub struct EventDecl {
    /// Which event.
    pub kind: EventKind,
    /// Its steps.
    pub steps: Vec<Step>,
    /// Where it is declared.
    pub loc: Loc,
}

/// Editor layout: node positions and comment boxes. Optional; never needed to run.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Editor {
    /// Node id → position on the canvas (x right, y down, editor units).
    pub positions: Vec<(Ident, [f64; 2])>,
    /// Comment frames.
    pub comments: Vec<Comment>,
}

/// A comment frame around nodes, as in the seed's screenshots.
#[derive(Clone, Debug, PartialEq)]
pub struct Comment {
    /// Title shown on the frame.
    pub title: String,
    /// RGB colour, 0..1.
    pub color: [f64; 3],
    /// Node ids inside the frame.
    pub nodes: Vec<Ident>,
}
