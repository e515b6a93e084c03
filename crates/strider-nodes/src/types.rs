//! Value types of graph pins and variables, and literal values.

use glam::{Quat, Vec3};
use std::fmt;
use strider_core::Transform;

/// The element type of an array, or the scalar type of a pin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Elem {
    /// `true` / `false`.
    Bool,
    /// 32-bit signed integer.
    Int,
    /// 32-bit float.
    Float,
    /// 3D vector (centimetres for positions).
    Vec3,
    /// Unit quaternion.
    Quat,
    /// Translation + rotation + scale.
    Transform,
    /// A bone of the instance's skeleton (or none).
    Bone,
}

impl Elem {
    /// Every element type.
    pub const ALL: [Elem; 7] = [
        Elem::Bool,
        Elem::Int,
        Elem::Float,
        Elem::Vec3,
        Elem::Quat,
        Elem::Transform,
        Elem::Bone,
    ];

    /// The scalar value type of this element.
    #[must_use]
    pub const fn scalar(self) -> ValueType {
        match self {
            Elem::Bool => ValueType::Bool,
            Elem::Int => ValueType::Int,
            Elem::Float => ValueType::Float,
            Elem::Vec3 => ValueType::Vec3,
            Elem::Quat => ValueType::Quat,
            Elem::Transform => ValueType::Transform,
            Elem::Bone => ValueType::Bone,
        }
    }

    /// The array value type of this element.
    #[must_use]
    pub const fn array(self) -> ValueType {
        ValueType::Array(self)
    }
}

/// The type of a pin, a variable or a slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ValueType {
    /// `true` / `false`.
    Bool,
    /// 32-bit signed integer.
    Int,
    /// 32-bit float.
    Float,
    /// 3D vector.
    Vec3,
    /// Unit quaternion.
    Quat,
    /// Translation + rotation + scale.
    Transform,
    /// A bone of the instance's skeleton, or none.
    Bone,
    /// A constant text, only written as a literal (`name("foot")`), e.g. a bone-name filter.
    Name,
    /// A growable array of one element type.
    Array(Elem),
}

impl ValueType {
    /// Every type, scalars first, then arrays.
    pub const ALL: [ValueType; 15] = [
        ValueType::Bool,
        ValueType::Int,
        ValueType::Float,
        ValueType::Vec3,
        ValueType::Quat,
        ValueType::Transform,
        ValueType::Bone,
        ValueType::Name,
        ValueType::Array(Elem::Bool),
        ValueType::Array(Elem::Int),
        ValueType::Array(Elem::Float),
        ValueType::Array(Elem::Vec3),
        ValueType::Array(Elem::Quat),
        ValueType::Array(Elem::Transform),
        ValueType::Array(Elem::Bone),
    ];

    /// The type's name as written in graph files (`Float`, `Vec3Array`, ...).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            ValueType::Bool => "Bool",
            ValueType::Int => "Int",
            ValueType::Float => "Float",
            ValueType::Vec3 => "Vec3",
            ValueType::Quat => "Quat",
            ValueType::Transform => "Transform",
            ValueType::Bone => "Bone",
            ValueType::Name => "Name",
            ValueType::Array(Elem::Bool) => "BoolArray",
            ValueType::Array(Elem::Int) => "IntArray",
            ValueType::Array(Elem::Float) => "FloatArray",
            ValueType::Array(Elem::Vec3) => "Vec3Array",
            ValueType::Array(Elem::Quat) => "QuatArray",
            ValueType::Array(Elem::Transform) => "TransformArray",
            ValueType::Array(Elem::Bone) => "BoneArray",
        }
    }

    /// The type called `name` in graph files.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|t| t.name() == name)
    }

    /// The scalar element type, for scalars and arrays (not for `Name`).
    #[must_use]
    pub const fn elem(self) -> Option<Elem> {
        match self {
            ValueType::Bool => Some(Elem::Bool),
            ValueType::Int => Some(Elem::Int),
            ValueType::Float => Some(Elem::Float),
            ValueType::Vec3 => Some(Elem::Vec3),
            ValueType::Quat => Some(Elem::Quat),
            ValueType::Transform => Some(Elem::Transform),
            ValueType::Bone => Some(Elem::Bone),
            ValueType::Name => None,
            ValueType::Array(e) => Some(e),
        }
    }

    /// True for array types.
    #[must_use]
    pub const fn is_array(self) -> bool {
        matches!(self, ValueType::Array(_))
    }

    /// Whether a value of type `self` may feed a pin of type `to`: equal types, or the one
    /// lossless implicit conversion, `Int → Float`.
    #[must_use]
    pub fn converts_to(self, to: ValueType) -> bool {
        self == to || (self == ValueType::Int && to == ValueType::Float)
    }

    /// The zero value of the type: false, 0, zero vector, identity rotation and transform,
    /// no bone, empty text, empty array.
    #[must_use]
    pub fn zero(self) -> Value {
        match self {
            ValueType::Bool => Value::Bool(false),
            ValueType::Int => Value::Int(0),
            ValueType::Float => Value::Float(0.0),
            ValueType::Vec3 => Value::Vec3(Vec3::ZERO),
            ValueType::Quat => Value::Quat(Quat::IDENTITY),
            ValueType::Transform => Value::Transform(Transform::IDENTITY),
            ValueType::Bone => Value::Bone(None),
            ValueType::Name => Value::Name(String::new()),
            ValueType::Array(e) => Value::Array(e, Vec::new()),
        }
    }
}

impl fmt::Display for ValueType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A typed constant: a pin default, a literal in a graph file, a variable's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A bool.
    Bool(bool),
    /// An int.
    Int(i32),
    /// A float.
    Float(f32),
    /// A vector.
    Vec3(Vec3),
    /// A rotation.
    Quat(Quat),
    /// A transform.
    Transform(Transform),
    /// A bone by name (resolved against the skeleton at instantiation), or none.
    Bone(Option<String>),
    /// A constant text.
    Name(String),
    /// An array; every element is a scalar of the given type.
    Array(Elem, Vec<Value>),
}

impl Value {
    /// The value's type.
    #[must_use]
    pub fn ty(&self) -> ValueType {
        match self {
            Value::Bool(_) => ValueType::Bool,
            Value::Int(_) => ValueType::Int,
            Value::Float(_) => ValueType::Float,
            Value::Vec3(_) => ValueType::Vec3,
            Value::Quat(_) => ValueType::Quat,
            Value::Transform(_) => ValueType::Transform,
            Value::Bone(_) => ValueType::Bone,
            Value::Name(_) => ValueType::Name,
            Value::Array(e, _) => ValueType::Array(*e),
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bool(b) => write!(f, "{b}"),
            Value::Int(i) => write!(f, "{i}"),
            Value::Float(x) => write!(f, "{x:?}"),
            Value::Vec3(v) => write!(f, "({:?}, {:?}, {:?})", v.x, v.y, v.z),
            Value::Quat(q) => write!(f, "({:?}, {:?}, {:?}, {:?})", q.x, q.y, q.z, q.w),
            Value::Transform(t) => {
                let (tr, r, s) = (t.translation, t.rotation, t.scale);
                write!(
                    f,
                    "(translation: ({:?}, {:?}, {:?}), rotation: ({:?}, {:?}, {:?}, {:?}), scale: ({:?}, {:?}, {:?}))",
                    tr.x, tr.y, tr.z, r.x, r.y, r.z, r.w, s.x, s.y, s.z
                )
            }
            Value::Bone(Some(b)) => write!(f, "bone({b:?})"),
            Value::Bone(None) => write!(f, "None"),
            Value::Name(s) => write!(f, "name({s:?})"),
            Value::Array(_, items) => {
                f.write_str("[")?;
                for (i, v) in items.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{v}")?;
                }
                f.write_str("]")
            }
        }
    }
}
