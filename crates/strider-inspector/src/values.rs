//! Showing values: short text for pins and variables, and reading a pin's value live or
//! from a recorded frame.

use crate::recording::RecordedFrame;
use std::fmt::Write as _;
use strider_core::Skeleton;
use strider_nodes::{Elem, Value, ValueType};
use strider_vm::Instance;

/// Where the panels read values: the live instance, or a recorded frame (time travel).
#[derive(Clone, Copy)]
pub enum ValueSource<'a> {
    /// The instance now.
    Live(&'a Instance),
    /// A recorded frame; `same_program` is false when it was recorded by an earlier
    /// program (its slots do not match the current program's layout).
    Recorded {
        /// The frame.
        frame: &'a RecordedFrame,
        /// Whether the frame was run by the current program.
        same_program: bool,
        /// The skeleton's bone names (storage order), to name recorded bones.
        bone_names: &'a [String],
    },
}

impl ValueSource<'_> {
    /// The value of slot `slot` of type `ty`, or `None` when not available (names and
    /// arrays over the recording's budget in recorded frames, frames of an earlier
    /// program).
    #[must_use]
    pub fn read(&self, ty: ValueType, slot: u32) -> Option<Value> {
        match self {
            ValueSource::Live(instance) => {
                let slots = instance.slots();
                if ty == ValueType::Bone {
                    return slots
                        .bones
                        .get(slot as usize)
                        .map(|&b| bone_value(instance, b));
                }
                if ty == ValueType::Array(Elem::Bone) {
                    return slots.bone_arrays.get(slot as usize).map(|a| {
                        Value::Array(
                            Elem::Bone,
                            a.iter().map(|&b| bone_value(instance, b)).collect(),
                        )
                    });
                }
                Some(slots.read(ty, slot))
            }
            ValueSource::Recorded {
                frame,
                same_program,
                bone_names,
            } => {
                if !same_program {
                    return None;
                }
                frame.slots.read(ty, slot, bone_names)
            }
        }
    }

    /// A float slot (for plots), `None` when not available.
    #[must_use]
    pub fn float(&self, slot: u32) -> Option<f32> {
        match self {
            ValueSource::Live(i) => i.slots().floats.get(slot as usize).copied(),
            ValueSource::Recorded {
                frame,
                same_program: true,
                ..
            } => frame.slots.floats.get(slot as usize).copied(),
            ValueSource::Recorded { .. } => None,
        }
    }
}

impl<'a> ValueSource<'a> {
    /// The values of recorded frame `shown` of `session` (`None` or the newest frame: the
    /// live instance, arrays included).
    #[must_use]
    pub fn of(session: &'a crate::Session, shown: Option<usize>) -> ValueSource<'a> {
        let recorder = session.recorder();
        match shown {
            Some(i) if i + 1 < recorder.len() => match recorder.get(i) {
                Some(frame) => ValueSource::Recorded {
                    frame,
                    same_program: frame.meta.generation == session.generation(),
                    bone_names: session.skeleton().skeleton.names(),
                },
                None => ValueSource::Live(session.instance()),
            },
            _ => ValueSource::Live(session.instance()),
        }
    }
}

fn bone_value(instance: &Instance, b: i32) -> Value {
    let names = instance.pose().skeleton().names();
    Value::Bone(usize::try_from(b).ok().and_then(|i| names.get(i).cloned()))
}

/// Short text for a value: numbers with 2 decimals, vectors as `(x, y, z)`, rotations as
/// Euler XYZ degrees, transforms as translation and rotation, arrays as their length and
/// first items.
#[must_use]
pub fn format_value(value: &Value) -> String {
    let mut s = String::new();
    write_value(&mut s, value);
    s
}

/// `x` without a minus sign when it prints as zero with `decimals` decimals.
fn tidy(x: f32, decimals: i32) -> f32 {
    let scale = 10f32.powi(decimals);
    if (x * scale).round() == 0.0 { 0.0 } else { x }
}

fn write_value(s: &mut String, value: &Value) {
    match value {
        Value::Bool(b) => {
            let _ = write!(s, "{b}");
        }
        Value::Int(i) => {
            let _ = write!(s, "{i}");
        }
        Value::Float(x) => {
            let _ = write!(s, "{:.2}", tidy(*x, 2));
        }
        Value::Vec3(v) => {
            let _ = write!(
                s,
                "({:.1}, {:.1}, {:.1})",
                tidy(v.x, 1),
                tidy(v.y, 1),
                tidy(v.z, 1)
            );
        }
        Value::Quat(q) => {
            let (x, y, z) = q.to_euler(glam::EulerRot::XYZ);
            let _ = write!(
                s,
                "euler({:.1}°, {:.1}°, {:.1}°)",
                tidy(x.to_degrees(), 1),
                tidy(y.to_degrees(), 1),
                tidy(z.to_degrees(), 1)
            );
        }
        Value::Transform(t) => {
            let v = t.translation;
            let _ = write!(
                s,
                "t({:.1}, {:.1}, {:.1}) r",
                tidy(v.x, 1),
                tidy(v.y, 1),
                tidy(v.z, 1)
            );
            write_value(s, &Value::Quat(t.rotation));
        }
        Value::Bone(Some(name)) => {
            let _ = write!(s, "bone(\"{name}\")");
        }
        Value::Bone(None) => s.push_str("None"),
        Value::Name(text) => {
            let _ = write!(s, "name(\"{text}\")");
        }
        Value::Array(_, items) => {
            let _ = write!(s, "[{}]", items.len());
            for (i, item) in items.iter().take(3).enumerate() {
                s.push_str(if i == 0 { " " } else { ", " });
                write_value(s, item);
            }
            if items.len() > 3 {
                s.push_str(", …");
            }
        }
    }
}

/// The name of bone `index` of `skeleton`, or `None`.
#[must_use]
pub fn bone_name(skeleton: &Skeleton, index: i32) -> Option<&str> {
    usize::try_from(index)
        .ok()
        .and_then(|i| skeleton.names().get(i))
        .map(String::as_str)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};

    #[test]
    fn values_print_short_and_in_the_rig_units() {
        assert_eq!(format_value(&Value::Float(1.0 / 3.0)), "0.33");
        assert_eq!(format_value(&Value::Float(-0.001)), "0.00", "no minus zero");
        assert_eq!(
            format_value(&Value::Vec3(Vec3::new(1.0, -2.26, 0.0))),
            "(1.0, -2.3, 0.0)"
        );
        // 90° about Z, in degrees.
        let q = Quat::from_rotation_z(std::f32::consts::FRAC_PI_2);
        assert_eq!(format_value(&Value::Quat(q)), "euler(0.0°, 0.0°, 90.0°)");
        let items = (1..=5).map(Value::Int).collect();
        assert_eq!(
            format_value(&Value::Array(strider_nodes::Elem::Int, items)),
            "[5] 1, 2, 3, …"
        );
    }
}
