//! The `--out` format: one JSON object per frame, one line each.
//!
//! ```text
//! {"frame":0,"time":0.016666666666666666,"bones":{"root":{"t":[0.0,0.0,0.0],"r":[0.0,0.0,0.0,1.0],"s":[1.0,1.0,1.0]},...}}
//! ```
//!
//! Runs driven by a scenario add `"world":{"t":...,"r":...,"s":...}` after `time`: the
//! component-to-world transform of the frame (world space, cm), so that world positions
//! are `world · global`.
//!
//! Written by hand rather than through a `serde_json::Map` so that bones come in the
//! skeleton's storage (depth-first) order, which keeps diffs between runs stable. `t` is
//! the rig-space translation (cm), `r` the rotation `(x, y, z, w)`, `s` the scale. Floats
//! are written in Rust's shortest round-trip form, so reading them back as `f32` gives
//! the exact values; NaN and infinities, which JSON cannot express, are written `null`.

use std::io::{self, Write};
use strider_core::Transform;

/// Writes one frame as a JSON line. `time` is seconds at the end of the frame; `world`, if
/// given, is the frame's component-to-world transform; `names` and `globals` are in the
/// skeleton's storage order.
///
/// Returns how many non-finite numbers were written as `null`.
pub(crate) fn write_frame(
    out: &mut impl Write,
    frame: u64,
    time: f64,
    world: Option<&Transform>,
    names: &[String],
    globals: &[Transform],
) -> io::Result<usize> {
    let mut non_finite = 0;
    write!(out, "{{\"frame\":{frame},\"time\":")?;
    non_finite += number(out, time)?;
    if let Some(w) = world {
        out.write_all(b",\"world\":{\"t\":")?;
        non_finite += array(out, &w.translation.to_array())?;
        out.write_all(b",\"r\":")?;
        non_finite += array(out, &w.rotation.to_array())?;
        out.write_all(b",\"s\":")?;
        non_finite += array(out, &w.scale.to_array())?;
        out.write_all(b"}")?;
    }
    out.write_all(b",\"bones\":{")?;
    for (i, (name, g)) in names.iter().zip(globals).enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        serde_json::to_writer(&mut *out, name.as_str()).map_err(io::Error::other)?;
        out.write_all(b":{\"t\":")?;
        non_finite += array(out, &g.translation.to_array())?;
        out.write_all(b",\"r\":")?;
        non_finite += array(out, &g.rotation.to_array())?;
        out.write_all(b",\"s\":")?;
        non_finite += array(out, &g.scale.to_array())?;
        out.write_all(b"}")?;
    }
    out.write_all(b"}}\n")?;
    Ok(non_finite)
}

/// How many components of the transforms are NaN or infinite.
pub(crate) fn count_non_finite(globals: &[Transform]) -> usize {
    globals
        .iter()
        .flat_map(|g| {
            g.translation
                .to_array()
                .into_iter()
                .chain(g.rotation.to_array())
                .chain(g.scale.to_array())
        })
        .filter(|x| !x.is_finite())
        .count()
}

fn array(out: &mut impl Write, values: &[f32]) -> io::Result<usize> {
    let mut non_finite = 0;
    out.write_all(b"[")?;
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            out.write_all(b",")?;
        }
        non_finite += number(out, v)?;
    }
    out.write_all(b"]")?;
    Ok(non_finite)
}

/// Writes a number in shortest round-trip form (`Debug` gives `1.0`, `0.1`, `1e-7`, all
/// valid JSON), or `null` when it is not finite; returns 1 for `null`.
fn number(out: &mut impl Write, v: impl Into<f64> + Copy + std::fmt::Debug) -> io::Result<usize> {
    if v.into().is_finite() {
        write!(out, "{v:?}")?;
        Ok(0)
    } else {
        out.write_all(b"null")?;
        Ok(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{Quat, Vec3};
    use serde_json::Value as Json;

    fn line(names: &[&str], globals: &[Transform], frame: u64, time: f64) -> (String, usize) {
        let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
        let mut buf = Vec::new();
        let n = write_frame(&mut buf, frame, time, None, &names, globals).unwrap();
        (String::from_utf8(buf).unwrap(), n)
    }

    fn f32s(v: &Json) -> Vec<f32> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap() as f32)
            .collect()
    }

    #[test]
    fn a_line_parses_back_to_the_numbers_written() {
        let pelvis = Transform::new(
            Vec3::new(0.1, -2.5, 95.000_01),
            Quat::from_xyzw(0.0, 0.0, 0.6, 0.8),
            Vec3::new(1.0, 1.0, 1.0),
        );
        let tiny = Transform::new(
            Vec3::new(1e-7, 3.0e20, -0.0),
            Quat::IDENTITY,
            Vec3::new(0.5, 2.0, f32::MIN_POSITIVE),
        );
        let (text, bad) = line(&["root\"x", "pelvis"], &[tiny, pelvis], 7, 8.0 / 60.0);
        assert_eq!(bad, 0);
        assert!(text.ends_with("}}\n") && text.matches('\n').count() == 1);
        let json: Json = serde_json::from_str(&text).unwrap();
        assert_eq!(json["frame"], 7);
        assert_eq!(json["time"].as_f64().unwrap(), 8.0 / 60.0);

        let p = &json["bones"]["pelvis"];
        assert_eq!(f32s(&p["t"]), [0.1f32, -2.5, 95.000_01]);
        assert_eq!(f32s(&p["r"]), [0.0f32, 0.0, 0.6, 0.8]);
        assert_eq!(f32s(&p["s"]), [1.0f32, 1.0, 1.0]);

        let r = &json["bones"]["root\"x"];
        assert_eq!(f32s(&r["t"]), [1e-7f32, 3.0e20, -0.0]);
        assert_eq!(f32s(&r["r"]), [0.0f32, 0.0, 0.0, 1.0]);
        assert_eq!(f32s(&r["s"]), [0.5f32, 2.0, f32::MIN_POSITIVE]);
    }

    #[test]
    fn bones_keep_storage_order() {
        let names = ["root", "pelvis", "b", "a"];
        let (text, _) = line(&names, &[Transform::IDENTITY; 4], 0, 1.0);
        let positions: Vec<usize> = names
            .iter()
            .map(|n| text.find(&format!("\"{n}\":")).unwrap())
            .collect();
        assert!(positions.windows(2).all(|w| w[0] < w[1]), "{text}");
    }

    #[test]
    fn non_finite_values_become_null_and_are_counted() {
        let mut t = Transform::IDENTITY;
        t.translation.x = f32::NAN;
        t.scale.z = f32::INFINITY;
        let (text, bad) = line(&["root"], &[t], 0, 1.0);
        assert_eq!(bad, 2);
        assert_eq!(count_non_finite(&[t, Transform::IDENTITY]), 2);
        let json: Json = serde_json::from_str(&text).unwrap();
        assert!(json["bones"]["root"]["t"][0].is_null());
        assert!(json["bones"]["root"]["s"][2].is_null());
        assert_eq!(json["bones"]["root"]["t"][1].as_f64(), Some(0.0));
    }
}
