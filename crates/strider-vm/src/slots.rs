//! Typed slot memory: one array per value type.

use glam::{Quat, Vec3};
use strider_core::Transform;
use strider_nodes::{Elem, Value, ValueType};

/// An instance's memory: variables, node outputs and constants, one array per type.
/// A slot is an index into the array of its type. Bones are stored as indices into the
/// instance's skeleton, `-1` for "no bone".
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Slots {
    /// Bool slots.
    pub bools: Vec<bool>,
    /// Int slots.
    pub ints: Vec<i32>,
    /// Float slots.
    pub floats: Vec<f32>,
    /// Vector slots.
    pub vec3s: Vec<Vec3>,
    /// Rotation slots.
    pub quats: Vec<Quat>,
    /// Transform slots.
    pub transforms: Vec<Transform>,
    /// Bone slots (bone index or -1).
    pub bones: Vec<i32>,
    /// Name slots: indices into the program's text table.
    pub names: Vec<u32>,
    /// Bool array slots.
    pub bool_arrays: Vec<Vec<bool>>,
    /// Int array slots.
    pub int_arrays: Vec<Vec<i32>>,
    /// Float array slots.
    pub float_arrays: Vec<Vec<f32>>,
    /// Vector array slots.
    pub vec3_arrays: Vec<Vec<Vec3>>,
    /// Rotation array slots.
    pub quat_arrays: Vec<Vec<Quat>>,
    /// Transform array slots.
    pub transform_arrays: Vec<Vec<Transform>>,
    /// Bone array slots.
    pub bone_arrays: Vec<Vec<i32>>,
}

/// The lengths the scalar slot arrays (bools, ints, floats, vectors, rotations,
/// transforms) must have at least: the executor indexes them without bounds checks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct ScalarLens(pub(crate) [usize; 6]);

/// The scalar slot types, in the order of [`ScalarLens`].
pub(crate) const SCALAR_TYPES: [ValueType; 6] = [
    ValueType::Bool,
    ValueType::Int,
    ValueType::Float,
    ValueType::Vec3,
    ValueType::Quat,
    ValueType::Transform,
];

/// Position of `ty` in [`SCALAR_TYPES`] (`None` for bones, names and arrays).
pub(crate) fn scalar(ty: ValueType) -> Option<usize> {
    SCALAR_TYPES.iter().position(|&t| t == ty)
}

impl ScalarLens {
    /// The lengths of `slots`' scalar arrays.
    pub(crate) fn of(slots: &Slots) -> Self {
        Self([
            slots.bools.len(),
            slots.ints.len(),
            slots.floats.len(),
            slots.vec3s.len(),
            slots.quats.len(),
            slots.transforms.len(),
        ])
    }
}

/// Grows `v` to `len` items with `zero`s if it is shorter.
#[inline]
fn grow_to<T: Clone>(v: &mut Vec<T>, len: usize, zero: T) {
    if v.len() < len {
        v.resize(len, zero);
    }
}

impl Slots {
    /// Bytes of heap memory the slots hold: every array's capacity, arrays of arrays
    /// with their elements' buffers.
    #[must_use]
    pub fn heap_bytes(&self) -> usize {
        fn flat<T>(v: &Vec<T>) -> usize {
            v.capacity() * std::mem::size_of::<T>()
        }
        fn nested<T>(v: &Vec<Vec<T>>) -> usize {
            flat(v) + v.iter().map(flat).sum::<usize>()
        }
        flat(&self.bools)
            + flat(&self.ints)
            + flat(&self.floats)
            + flat(&self.vec3s)
            + flat(&self.quats)
            + flat(&self.transforms)
            + flat(&self.bones)
            + flat(&self.names)
            + nested(&self.bool_arrays)
            + nested(&self.int_arrays)
            + nested(&self.float_arrays)
            + nested(&self.vec3_arrays)
            + nested(&self.quat_arrays)
            + nested(&self.transform_arrays)
            + nested(&self.bone_arrays)
    }

    /// Grows the scalar arrays (with zeroed slots) to at least `lens`. Does nothing, and
    /// costs six comparisons, when they are long enough.
    #[inline]
    pub(crate) fn cover(&mut self, lens: &ScalarLens) {
        let [b, i, f, v, q, t] = lens.0;
        grow_to(&mut self.bools, b, false);
        grow_to(&mut self.ints, i, 0);
        grow_to(&mut self.floats, f, 0.0);
        grow_to(&mut self.vec3s, v, Vec3::ZERO);
        grow_to(&mut self.quats, q, Quat::IDENTITY);
        grow_to(&mut self.transforms, t, Transform::IDENTITY);
    }

    /// Grows the array of scalar type `ty` so that slot `index` exists (other types: no
    /// effect; a program's array variables are checked to exist when it is finished, and
    /// bone and name slots are bounds-checked).
    pub(crate) fn cover_slot(&mut self, ty: ValueType, index: u32) {
        let len = index as usize + 1;
        match ty {
            ValueType::Bool => grow_to(&mut self.bools, len, false),
            ValueType::Int => grow_to(&mut self.ints, len, 0),
            ValueType::Float => grow_to(&mut self.floats, len, 0.0),
            ValueType::Vec3 => grow_to(&mut self.vec3s, len, Vec3::ZERO),
            ValueType::Quat => grow_to(&mut self.quats, len, Quat::IDENTITY),
            ValueType::Transform => grow_to(&mut self.transforms, len, Transform::IDENTITY),
            ValueType::Bone | ValueType::Name | ValueType::Array(_) => {}
        }
    }

    /// Whether array variable `index` of element type `e` exists.
    pub(crate) fn has_array(&self, e: Elem, index: u32) -> bool {
        let i = index as usize;
        match e {
            Elem::Bool => i < self.bool_arrays.len(),
            Elem::Int => i < self.int_arrays.len(),
            Elem::Float => i < self.float_arrays.len(),
            Elem::Vec3 => i < self.vec3_arrays.len(),
            Elem::Quat => i < self.quat_arrays.len(),
            Elem::Transform => i < self.transform_arrays.len(),
            Elem::Bone => i < self.bone_arrays.len(),
        }
    }

    /// Bit-for-bit equality of every slot, arrays included (floats compared by their bits,
    /// so NaN equals an identical NaN): what determinism checks compare.
    #[must_use]
    pub fn bit_eq(&self, other: &Slots) -> bool {
        fn same<T, B: PartialEq>(a: &[T], b: &[T], bits: impl Fn(&T) -> B) -> bool {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| bits(x) == bits(y))
        }
        fn same_arrays<T, B: PartialEq>(
            a: &[Vec<T>],
            b: &[Vec<T>],
            bits: impl Fn(&T) -> B,
        ) -> bool {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(x, y, &bits))
        }
        let f = |x: &f32| x.to_bits();
        let v = |x: &Vec3| x.to_array().map(f32::to_bits);
        let q = |x: &Quat| x.to_array().map(f32::to_bits);
        let t = Transform::to_bits;
        self.bools == other.bools
            && self.ints == other.ints
            && self.bones == other.bones
            && self.names == other.names
            && same(&self.floats, &other.floats, f)
            && same(&self.vec3s, &other.vec3s, v)
            && same(&self.quats, &other.quats, q)
            && same(&self.transforms, &other.transforms, t)
            && self.bool_arrays == other.bool_arrays
            && self.int_arrays == other.int_arrays
            && self.bone_arrays == other.bone_arrays
            && same_arrays(&self.float_arrays, &other.float_arrays, f)
            && same_arrays(&self.vec3_arrays, &other.vec3_arrays, v)
            && same_arrays(&self.quat_arrays, &other.quat_arrays, q)
            && same_arrays(&self.transform_arrays, &other.transform_arrays, t)
    }

    /// Adds a zeroed slot of type `ty` and returns its index.
    pub fn alloc(&mut self, ty: ValueType) -> u32 {
        fn push<T>(v: &mut Vec<T>, x: T) -> u32 {
            v.push(x);
            (v.len() - 1) as u32
        }
        match ty {
            ValueType::Bool => push(&mut self.bools, false),
            ValueType::Int => push(&mut self.ints, 0),
            ValueType::Float => push(&mut self.floats, 0.0),
            ValueType::Vec3 => push(&mut self.vec3s, Vec3::ZERO),
            ValueType::Quat => push(&mut self.quats, Quat::IDENTITY),
            ValueType::Transform => push(&mut self.transforms, Transform::IDENTITY),
            ValueType::Bone => push(&mut self.bones, -1),
            ValueType::Name => push(&mut self.names, 0),
            ValueType::Array(Elem::Bool) => push(&mut self.bool_arrays, Vec::new()),
            ValueType::Array(Elem::Int) => push(&mut self.int_arrays, Vec::new()),
            ValueType::Array(Elem::Float) => push(&mut self.float_arrays, Vec::new()),
            ValueType::Array(Elem::Vec3) => push(&mut self.vec3_arrays, Vec::new()),
            ValueType::Array(Elem::Quat) => push(&mut self.quat_arrays, Vec::new()),
            ValueType::Array(Elem::Transform) => push(&mut self.transform_arrays, Vec::new()),
            ValueType::Array(Elem::Bone) => push(&mut self.bone_arrays, Vec::new()),
        }
    }

    /// Writes a value into slot `slot` of the value's type. Bones and names are not
    /// resolved here: a bone value writes "no bone", a name writes nothing (the program
    /// builder places both).
    pub fn write(&mut self, slot: u32, value: &Value) {
        let s = slot as usize;
        match value {
            Value::Bool(b) => self.bools[s] = *b,
            Value::Int(i) => self.ints[s] = *i,
            Value::Float(x) => self.floats[s] = *x,
            Value::Vec3(v) => self.vec3s[s] = *v,
            Value::Quat(q) => self.quats[s] = *q,
            Value::Transform(t) => self.transforms[s] = *t,
            Value::Bone(_) => self.bones[s] = -1,
            Value::Name(_) => {}
            Value::Array(e, items) => match e {
                Elem::Bool => {
                    self.bool_arrays[s] = items
                        .iter()
                        .map(|v| matches!(v, Value::Bool(true)))
                        .collect()
                }
                Elem::Int => {
                    self.int_arrays[s] = items
                        .iter()
                        .map(|v| if let Value::Int(i) = v { *i } else { 0 })
                        .collect()
                }
                Elem::Float => {
                    self.float_arrays[s] = items
                        .iter()
                        .map(|v| match v {
                            Value::Float(x) => *x,
                            Value::Int(i) => *i as f32,
                            _ => 0.0,
                        })
                        .collect();
                }
                Elem::Vec3 => {
                    self.vec3_arrays[s] = items
                        .iter()
                        .map(|v| {
                            if let Value::Vec3(x) = v {
                                *x
                            } else {
                                Vec3::ZERO
                            }
                        })
                        .collect()
                }
                Elem::Quat => {
                    self.quat_arrays[s] = items
                        .iter()
                        .map(|v| {
                            if let Value::Quat(x) = v {
                                *x
                            } else {
                                Quat::IDENTITY
                            }
                        })
                        .collect()
                }
                Elem::Transform => {
                    self.transform_arrays[s] = items
                        .iter()
                        .map(|v| {
                            if let Value::Transform(x) = v {
                                *x
                            } else {
                                Transform::IDENTITY
                            }
                        })
                        .collect();
                }
                Elem::Bone => self.bone_arrays[s] = vec![-1; items.len()],
            },
        }
    }

    /// Reads slot `slot` of type `ty` as a [`Value`] (allocates for arrays; for
    /// inspection, not for the frame loop). Bones read as `Bone(None)`; use the instance's
    /// `variable` to get bone names.
    #[must_use]
    pub fn read(&self, ty: ValueType, slot: u32) -> Value {
        let s = slot as usize;
        match ty {
            ValueType::Bool => Value::Bool(self.bools[s]),
            ValueType::Int => Value::Int(self.ints[s]),
            ValueType::Float => Value::Float(self.floats[s]),
            ValueType::Vec3 => Value::Vec3(self.vec3s[s]),
            ValueType::Quat => Value::Quat(self.quats[s]),
            ValueType::Transform => Value::Transform(self.transforms[s]),
            ValueType::Bone => Value::Bone(None),
            ValueType::Name => Value::Name(String::new()),
            ValueType::Array(e) => {
                let items: Vec<Value> = match e {
                    Elem::Bool => self.bool_arrays[s]
                        .iter()
                        .map(|&b| Value::Bool(b))
                        .collect(),
                    Elem::Int => self.int_arrays[s].iter().map(|&i| Value::Int(i)).collect(),
                    Elem::Float => self.float_arrays[s]
                        .iter()
                        .map(|&x| Value::Float(x))
                        .collect(),
                    Elem::Vec3 => self.vec3_arrays[s]
                        .iter()
                        .map(|&x| Value::Vec3(x))
                        .collect(),
                    Elem::Quat => self.quat_arrays[s]
                        .iter()
                        .map(|&x| Value::Quat(x))
                        .collect(),
                    Elem::Transform => self.transform_arrays[s]
                        .iter()
                        .map(|&x| Value::Transform(x))
                        .collect(),
                    Elem::Bone => self.bone_arrays[s]
                        .iter()
                        .map(|_| Value::Bone(None))
                        .collect(),
                };
                Value::Array(e, items)
            }
        }
    }
}
