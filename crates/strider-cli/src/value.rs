//! Parsing `--set NAME=VALUE` values according to the variable's type.

use anyhow::{Context as _, anyhow, bail};
use glam::{Quat, Vec3};
use strider_nodes::{Value, ValueType};

/// How far from 1 a `--set` quaternion's length may be before it is refused rather than
/// normalised (the same tolerance skeleton files get).
const QUAT_TOLERANCE: f32 = 1e-3;

/// Splits `NAME=VALUE` at the first `=`; the name is trimmed, and must not be empty.
pub(crate) fn split_assignment(text: &str) -> anyhow::Result<(&str, &str)> {
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| anyhow!("`--set {text}`: expected NAME=VALUE"))?;
    let name = name.trim();
    if name.is_empty() {
        bail!("`--set {text}`: the variable name is empty; expected NAME=VALUE");
    }
    Ok((name, value))
}

/// Parses `text` as a value of type `ty`:
///
/// - `Float`: `3.5`, `-2`, `1e-3` (finite);
/// - `Int`: `3`, `-7` (32-bit);
/// - `Bool`: `true` or `false`;
/// - `Vec3`: `x,y,z` or `(x,y,z)`, spaces allowed;
/// - `Quat`: `x,y,z,w` or `(x,y,z,w)`, unit length (normalised if within 1e-3).
///
/// Other types cannot be set from the command line.
///
/// # Errors
/// A one-line message saying what was expected.
pub(crate) fn parse_value(ty: ValueType, text: &str) -> anyhow::Result<Value> {
    let t = text.trim();
    Ok(match ty {
        ValueType::Float => Value::Float(float(t).context("expected a number such as `3.5`")?),
        ValueType::Int => Value::Int(
            t.parse::<i32>()
                .map_err(|_| anyhow!("`{t}` is not a whole number; expected e.g. `3` or `-2`"))?,
        ),
        ValueType::Bool => match t {
            "true" => Value::Bool(true),
            "false" => Value::Bool(false),
            _ => bail!("`{t}` is not a Bool; expected `true` or `false`"),
        },
        ValueType::Vec3 => {
            let [x, y, z] = numbers::<3>(t).context("expected a vector as `x,y,z` or `(x,y,z)`")?;
            Value::Vec3(Vec3::new(x, y, z))
        }
        ValueType::Quat => {
            let [x, y, z, w] = numbers::<4>(t)
                .context("expected a unit quaternion as `x,y,z,w` or `(x,y,z,w)`")?;
            let q = Quat::from_xyzw(x, y, z, w);
            let length = q.length();
            if (length - 1.0).abs() > QUAT_TOLERANCE {
                bail!(
                    "`{t}` is not a unit quaternion (length {length}); give `x,y,z,w` with \
                     x² + y² + z² + w² = 1"
                );
            }
            Value::Quat(q.normalize())
        }
        other => bail!(
            "variables of type {other} cannot be set from the command line (only Float, Int, \
             Bool, Vec3 and Quat)"
        ),
    })
}

/// A finite `f32`.
fn float(t: &str) -> anyhow::Result<f32> {
    match t.parse::<f32>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => bail!("`{t}` is not a finite number"),
        Err(_) => bail!("`{t}` is not a number"),
    }
}

/// `N` comma-separated finite numbers, optionally in parentheses.
fn numbers<const N: usize>(t: &str) -> anyhow::Result<[f32; N]> {
    let inner = match t.strip_prefix('(') {
        Some(rest) => rest
            .strip_suffix(')')
            .ok_or_else(|| anyhow!("`{t}`: unbalanced parenthesis"))?,
        None => t,
    };
    let parts: Vec<&str> = inner.split(',').map(str::trim).collect();
    if parts.len() != N {
        bail!("`{t}` has {} components, not {N}", parts.len());
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(&parts) {
        *o = float(p).with_context(|| format!("in `{t}`"))?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use strider_nodes::Elem;

    fn ok(ty: ValueType, text: &str) -> Value {
        parse_value(ty, text).unwrap_or_else(|e| panic!("{text:?} as {ty}: {e:#}"))
    }

    fn err(ty: ValueType, text: &str) -> String {
        match parse_value(ty, text) {
            Ok(v) => panic!("{text:?} as {ty} accepted as {v}"),
            Err(e) => format!("{e:#}"),
        }
    }

    #[test]
    fn parses_every_settable_type() {
        assert_eq!(ok(ValueType::Float, "3.5"), Value::Float(3.5));
        assert_eq!(ok(ValueType::Float, "3"), Value::Float(3.0));
        assert_eq!(ok(ValueType::Float, " -0.25 "), Value::Float(-0.25));
        assert_eq!(ok(ValueType::Float, "1e-3"), Value::Float(1e-3));
        assert_eq!(ok(ValueType::Int, "3"), Value::Int(3));
        assert_eq!(ok(ValueType::Int, "-7"), Value::Int(-7));
        assert_eq!(ok(ValueType::Bool, "true"), Value::Bool(true));
        assert_eq!(ok(ValueType::Bool, "false"), Value::Bool(false));
        assert_eq!(
            ok(ValueType::Vec3, "1,2,3"),
            Value::Vec3(Vec3::new(1.0, 2.0, 3.0))
        );
        assert_eq!(
            ok(ValueType::Vec3, "( 1.5, -2 , 0 )"),
            Value::Vec3(Vec3::new(1.5, -2.0, 0.0))
        );
        assert_eq!(ok(ValueType::Quat, "0,0,0,1"), Value::Quat(Quat::IDENTITY));
        let Value::Quat(q) = ok(ValueType::Quat, "(0, 0, 0.7071068, 0.7071068)") else {
            panic!()
        };
        assert!((q.length() - 1.0).abs() < 1e-6);
        assert!((q.z - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-6);
    }

    #[test]
    fn malformed_values_are_errors() {
        for t in [
            "", "abc", "1,2", "nan", "NaN", "inf", "-inf", "1e40", "3.5.1",
        ] {
            err(ValueType::Float, t);
        }
        for t in ["", "3.5", "1e3", "99999999999", "three", "0x10"] {
            err(ValueType::Int, t);
        }
        for t in ["", "1", "0", "yes", "True", "TRUE"] {
            err(ValueType::Bool, t);
        }
        for t in [
            "",
            "1,2",
            "1,2,3,4",
            "(1,2,3",
            "1,2,3)",
            "((1,2,3))",
            "1,,3",
            "1,2,x",
            "1;2;3",
            "1,nan,3",
            "1,2,inf",
        ] {
            err(ValueType::Vec3, t);
        }
        for t in [
            "",
            "0,0,0",
            "0,0,0,0",
            "1,1,1,1",
            "0,0,0,2",
            "0,0,0,nan",
            "(0,0,0,1",
        ] {
            err(ValueType::Quat, t);
        }
        assert!(err(ValueType::Quat, "1,1,1,1").contains("unit quaternion"));
        assert!(err(ValueType::Vec3, "1,2").contains("2 components, not 3"));
    }

    #[test]
    fn unsupported_types_say_so() {
        for ty in [
            ValueType::Transform,
            ValueType::Bone,
            ValueType::Name,
            ValueType::Array(Elem::Float),
        ] {
            assert!(err(ty, "1").contains("cannot be set from the command line"));
        }
    }

    #[test]
    fn splits_assignments() {
        assert_eq!(split_assignment("A=1").unwrap(), ("A", "1"));
        assert_eq!(split_assignment(" A =x=y").unwrap(), ("A", "x=y"));
        assert_eq!(split_assignment("A=").unwrap(), ("A", ""));
        assert!(split_assignment("A").is_err());
        assert!(split_assignment("=1").is_err());
        assert!(split_assignment("").is_err());
    }

    #[test]
    fn never_panics_on_odd_input() {
        let odd = [
            "\u{0}",
            "é",
            "(",
            ")",
            "()",
            ",",
            ",,,",
            "((",
            "(é,é,é)",
            "🦀",
            "-",
            "+",
            ".",
        ];
        for ty in ValueType::ALL {
            for t in odd {
                let _ = parse_value(ty, t);
            }
        }
    }
}
