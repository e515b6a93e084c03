//! Literal conversion: a constant as written, typed by the pin or variable it feeds.

use glam::{Quat, Vec3};
use strider_core::Transform;
use strider_graph::{Literal, LiteralKind};
use strider_nodes::{Elem, Value, ValueType};

/// How well a literal fits a type: exactly, or through the int → float conversion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Fit {
    Exact,
    Promoted,
}

/// Converts `lit` to a value of type `ty`. `choices` names the values of an `Int` mode
/// pin. Errors are worded for the file's author.
pub(crate) fn convert(
    lit: &Literal,
    ty: ValueType,
    choices: &[&str],
) -> Result<(Value, Fit), String> {
    use LiteralKind as L;
    let found = || describe(lit);
    match (&lit.kind, ty) {
        (L::Bool(b), ValueType::Bool) => Ok((Value::Bool(*b), Fit::Exact)),
        (L::Int(i), ValueType::Int) => i32::try_from(*i)
            .map(|i| (Value::Int(i), Fit::Exact))
            .map_err(|_| format!("{i} does not fit in a 32-bit Int")),
        (L::Int(i), ValueType::Float) => Ok((Value::Float(*i as f32), Fit::Promoted)),
        (L::Float(f), ValueType::Float) => float(*f).map(|f| (Value::Float(f), Fit::Exact)),
        (L::Word(w), ValueType::Int) if !choices.is_empty() => {
            match choices.iter().position(|c| c == w) {
                Some(i) => Ok((Value::Int(i as i32), Fit::Exact)),
                None => Err(format!("`{w}` is not one of {}", choices.join(", "))),
            }
        }
        (L::Numbers(n), ValueType::Vec3) if n.len() == 3 => {
            vec3(n).map(|v| (Value::Vec3(v), Fit::Exact))
        }
        (L::Numbers(_) | L::Euler(_), ValueType::Quat) => {
            quat(lit).map(|q| (Value::Quat(q), Fit::Exact))
        }
        (
            L::Transform {
                translation,
                rotation,
                scale,
            },
            ValueType::Transform,
        ) => {
            let mut t = Transform::IDENTITY;
            if let Some(l) = translation {
                t.translation = match &l.kind {
                    L::Numbers(n) if n.len() == 3 => vec3(n)?,
                    _ => {
                        return Err(format!(
                            "a translation is (x, y, z) in cm, found {}",
                            describe(l)
                        ));
                    }
                };
            }
            if let Some(l) = rotation {
                t.rotation = quat(l)?;
            }
            if let Some(l) = scale {
                t.scale = match &l.kind {
                    L::Numbers(n) if n.len() == 3 => vec3(n)?,
                    _ => return Err(format!("a scale is (x, y, z), found {}", describe(l))),
                };
            }
            Ok((Value::Transform(t), Fit::Exact))
        }
        (L::Bone(name), ValueType::Bone) => Ok((Value::Bone(Some(name.clone())), Fit::Exact)),
        (L::NoBone, ValueType::Bone) => Ok((Value::Bone(None), Fit::Exact)),
        (L::Name(text), ValueType::Name) => Ok((Value::Name(text.clone()), Fit::Exact)),
        (L::List(items), ValueType::Array(e)) => {
            let mut out = Vec::with_capacity(items.len());
            let mut fit = Fit::Exact;
            for (i, item) in items.iter().enumerate() {
                let (v, f) =
                    convert(item, e.scalar(), &[]).map_err(|m| format!("element {i}: {m}"))?;
                fit = fit.max(f);
                out.push(v);
            }
            Ok((Value::Array(e, out), fit))
        }
        _ => Err(format!("expected {}, found {}", expectation(ty), found())),
    }
}

/// The type a literal has on its own, for messages and overload hints.
pub(crate) fn natural_type(lit: &Literal) -> Option<ValueType> {
    use LiteralKind as L;
    Some(match &lit.kind {
        L::Bool(_) => ValueType::Bool,
        L::Int(_) => ValueType::Int,
        L::Float(_) => ValueType::Float,
        L::Numbers(n) if n.len() == 3 => ValueType::Vec3,
        L::Numbers(_) | L::Euler(_) => ValueType::Quat,
        L::Transform { .. } => ValueType::Transform,
        L::Bone(_) | L::NoBone => ValueType::Bone,
        L::Name(_) => ValueType::Name,
        L::List(items) => ValueType::Array(
            items
                .first()
                .and_then(natural_type)
                .and_then(|t| t.elem())
                .unwrap_or(Elem::Float),
        ),
        L::Word(_) => return None,
    })
}

fn float(f: f64) -> Result<f32, String> {
    let x = f as f32;
    if f.is_finite() && !x.is_finite() {
        Err(format!("{f} is too large for a 32-bit float"))
    } else {
        Ok(x)
    }
}

fn vec3(n: &[f64]) -> Result<Vec3, String> {
    Ok(Vec3::new(float(n[0])?, float(n[1])?, float(n[2])?))
}

fn quat(lit: &Literal) -> Result<Quat, String> {
    match &lit.kind {
        LiteralKind::Numbers(n) if n.len() == 4 => {
            let q = Quat::from_xyzw(float(n[0])?, float(n[1])?, float(n[2])?, float(n[3])?);
            let len = q.length();
            if (len - 1.0).abs() > 1e-3 {
                return Err(format!(
                    "quaternion (x, y, z, w) has length {len}, not 1; write a unit quaternion or euler(x, y, z) in degrees"
                ));
            }
            Ok(q)
        }
        LiteralKind::Euler(e) => {
            let v = Vec3::new(float(e[0])?, float(e[1])?, float(e[2])?);
            Ok(strider_core::euler::quat_from_euler(
                v,
                strider_core::EulerOrder::XYZ,
            ))
        }
        _ => Err(format!(
            "a rotation is (x, y, z, w) or euler(x, y, z), found {}",
            describe(lit)
        )),
    }
}

fn expectation(ty: ValueType) -> String {
    match ty {
        ValueType::Bool => "Bool (true or false)".into(),
        ValueType::Int => "Int (a whole number)".into(),
        ValueType::Float => "Float (a number)".into(),
        ValueType::Vec3 => "Vec3 (x, y, z)".into(),
        ValueType::Quat => "Quat (x, y, z, w) or euler(x, y, z)".into(),
        ValueType::Transform => "Transform (translation: .., rotation: .., scale: ..)".into(),
        ValueType::Bone => "Bone bone(\"name\") or None".into(),
        ValueType::Name => "Name name(\"text\")".into(),
        ValueType::Array(e) => format!("{ty} [{}, ...]", e.scalar()),
    }
}

/// A literal as a person would name it in a message.
pub(crate) fn describe(lit: &Literal) -> String {
    use LiteralKind as L;
    match &lit.kind {
        L::Bool(b) => format!("Bool {b}"),
        L::Int(i) => format!("Int {i}"),
        L::Float(f) => format!("Float {f}"),
        L::Numbers(n) if n.len() == 3 => "a Vec3 (x, y, z)".into(),
        L::Numbers(_) => "a Quat (x, y, z, w)".into(),
        L::Euler(_) => "euler(...)".into(),
        L::Transform { .. } => "a Transform".into(),
        L::Bone(b) => format!("bone(\"{b}\")"),
        L::NoBone => "None".into(),
        L::Name(n) => format!("name(\"{n}\")"),
        L::Word(w) => format!("the word `{w}`"),
        L::List(_) => "a list".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lit(kind: LiteralKind) -> Literal {
        Literal {
            kind,
            loc: strider_graph::Loc::default(),
        }
    }

    #[test]
    fn int_literals_promote_to_float_and_nothing_else_converts() {
        assert_eq!(
            convert(&lit(LiteralKind::Int(3)), ValueType::Float, &[]),
            Ok((Value::Float(3.0), Fit::Promoted))
        );
        assert!(convert(&lit(LiteralKind::Float(1.5)), ValueType::Int, &[]).is_err());
        assert!(convert(&lit(LiteralKind::Int(1)), ValueType::Bool, &[]).is_err());
        assert!(
            convert(
                &lit(LiteralKind::Int(i64::from(i32::MAX) + 1)),
                ValueType::Int,
                &[]
            )
            .is_err()
        );
    }

    #[test]
    fn quaternions_must_be_unit_and_euler_is_degrees() {
        let err = convert(
            &lit(LiteralKind::Numbers(vec![0.0, 0.0, 0.0, 2.0])),
            ValueType::Quat,
            &[],
        )
        .unwrap_err();
        assert!(err.contains("length 2"), "{err}");
        let (Value::Quat(q), _) = convert(
            &lit(LiteralKind::Euler([0.0, 0.0, 90.0])),
            ValueType::Quat,
            &[],
        )
        .unwrap() else {
            panic!()
        };
        // 90° about Z: (0, 0, sin 45°, cos 45°).
        let h = std::f32::consts::FRAC_1_SQRT_2;
        assert!((q.z - h).abs() < 1e-6 && (q.w - h).abs() < 1e-6);
    }

    #[test]
    fn words_select_named_choices() {
        let choices = ["Global", "Local"];
        assert_eq!(
            convert(
                &lit(LiteralKind::Word("Local".into())),
                ValueType::Int,
                &choices
            ),
            Ok((Value::Int(1), Fit::Exact))
        );
        let err = convert(
            &lit(LiteralKind::Word("World".into())),
            ValueType::Int,
            &choices,
        )
        .unwrap_err();
        assert_eq!(err, "`World` is not one of Global, Local");
    }

    #[test]
    fn lists_convert_element_by_element() {
        let l = lit(LiteralKind::List(vec![
            lit(LiteralKind::Int(1)),
            lit(LiteralKind::Float(2.5)),
        ]));
        assert_eq!(
            convert(&l, ValueType::Array(Elem::Float), &[]),
            Ok((
                Value::Array(Elem::Float, vec![Value::Float(1.0), Value::Float(2.5)]),
                Fit::Promoted
            ))
        );
        let bad = lit(LiteralKind::List(vec![lit(LiteralKind::Bool(true))]));
        assert!(
            convert(&bad, ValueType::Array(Elem::Float), &[])
                .unwrap_err()
                .starts_with("element 0:")
        );
    }
}
