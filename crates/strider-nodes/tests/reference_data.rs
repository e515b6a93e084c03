//! Strider's spline kernel and Euler conventions checked against reference data generated
//! by SciPy (`tests/reference/*.py`, run by hand; the CSVs are checked in).
//!
//! - `bspline.csv` / `bspline_points.csv`: `scipy.interpolate.BSpline` on the clamped
//!   uniform knot vector, position and dP/dU at 21 values of U per control polygon.
//! - `euler.csv`: `scipy.spatial.transform.Rotation.from_euler` with extrinsic `'xyz'`
//!   (our `XYZ`) and `'zyx'` (our `ZYX`), quaternions scalar-last.

use glam::{DQuat, Quat, Vec3};
use strider_core::EulerOrder;
use strider_core::euler::{euler_from_quat, quat_from_euler};
use strider_nodes::kernels::spline::{SplineMode, evaluate};

const BSPLINE_CSV: &str = include_str!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/reference/bspline.csv"
));
const POINTS_CSV: &str = include_str!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/reference/bspline_points.csv"
));
const EULER_CSV: &str = include_str!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../tests/reference/euler.csv"
));

/// Position tolerance against SciPy (cm).
const POSITION_TOL: f64 = 1e-3;
/// Tangent tolerance against SciPy (cm per unit U).
const TANGENT_TOL: f64 = 1e-2;

/// The data rows of a CSV with the expected header, split on commas.
fn rows<'a>(csv: &'a str, header: &str) -> Vec<Vec<&'a str>> {
    let mut lines = csv.lines().filter(|l| !l.trim().is_empty());
    assert_eq!(
        lines.next().map(str::trim),
        Some(header),
        "unexpected header"
    );
    lines
        .map(|l| l.trim().split(',').map(str::trim).collect::<Vec<_>>())
        .inspect(|r| assert_eq!(r.len(), header.split(',').count(), "bad row {r:?}"))
        .collect()
}

fn num(field: &str) -> f64 {
    field
        .parse()
        .unwrap_or_else(|e| panic!("not a number: {field:?} ({e})"))
}

fn vec3(fields: &[&str]) -> Vec3 {
    Vec3::new(
        num(fields[0]) as f32,
        num(fields[1]) as f32,
        num(fields[2]) as f32,
    )
}

/// Distance between an f32 result and an f64 reference.
fn dist(ours: Vec3, x: f64, y: f64, z: f64) -> f64 {
    let d = [ours.x as f64 - x, ours.y as f64 - y, ours.z as f64 - z];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

/// Control points per case, in file order.
fn control_points() -> Vec<(String, Vec<Vec3>)> {
    let mut cases: Vec<(String, Vec<Vec3>)> = Vec::new();
    for r in rows(POINTS_CSV, "case,i,x,y,z") {
        let i: usize = r[1].parse().expect("point index");
        if cases.last().is_none_or(|(name, _)| name != r[0]) {
            cases.push((r[0].to_string(), Vec::new()));
        }
        let (_, pts) = cases.last_mut().expect("just pushed");
        assert_eq!(pts.len(), i, "points of {} out of order", r[0]);
        pts.push(vec3(&r[2..5]));
    }
    cases
}

#[test]
fn bspline_matches_scipy() {
    let cases = control_points();
    let mut counts = vec![0usize; cases.len()];
    let (mut max_pos, mut max_tan) = (0.0f64, 0.0f64);
    for r in rows(BSPLINE_CSV, "case,n,u,px,py,pz,tx,ty,tz") {
        let idx = cases
            .iter()
            .position(|(name, _)| name == r[0])
            .unwrap_or_else(|| panic!("no control points for case {}", r[0]));
        let pts = &cases[idx].1;
        assert_eq!(pts.len(), r[1].parse::<usize>().expect("n"), "{}", r[0]);
        counts[idx] += 1;
        let u = num(r[2]) as f32;
        let (p, t) = evaluate(pts, u, SplineMode::BSpline);
        let ep = dist(p, num(r[3]), num(r[4]), num(r[5]));
        let et = dist(t, num(r[6]), num(r[7]), num(r[8]));
        assert!(
            ep <= POSITION_TOL,
            "{} u={u}: position {p} vs SciPy ({}, {}, {}), error {ep}",
            r[0],
            r[3],
            r[4],
            r[5]
        );
        assert!(
            et <= TANGENT_TOL,
            "{} u={u}: tangent {t} vs SciPy ({}, {}, {}), error {et}",
            r[0],
            r[6],
            r[7],
            r[8]
        );
        max_pos = max_pos.max(ep);
        max_tan = max_tan.max(et);
    }
    for ((name, pts), count) in cases.iter().zip(&counts) {
        assert!(
            (11..=21).contains(count),
            "{name}: {count} samples ({} points)",
            pts.len()
        );
    }
    // The polygons the brief asks for: N = 2, 3, 4, 5 and 7, with the foot swing.
    for n in [2, 3, 4, 5, 7] {
        assert!(
            cases.iter().any(|(_, p)| p.len() == n),
            "no case with {n} points"
        );
    }
    assert!(cases.iter().any(|(name, _)| name == "swing7"));
    println!("B-spline vs SciPy: max position error {max_pos:e} cm, max tangent error {max_tan:e}");
}

/// Euler rows: order, angles (degrees) and SciPy's quaternion (x, y, z, w).
fn euler_rows() -> Vec<(EulerOrder, Vec3, DQuat)> {
    rows(EULER_CSV, "order,ex,ey,ez,qx,qy,qz,qw")
        .into_iter()
        .map(|r| {
            let order = match r[0] {
                "XYZ" => EulerOrder::XYZ,
                "ZYX" => EulerOrder::ZYX,
                other => panic!("unknown order {other}"),
            };
            let q = DQuat::from_xyzw(num(r[4]), num(r[5]), num(r[6]), num(r[7]));
            (order, vec3(&r[1..4]), q)
        })
        .collect()
}

fn abs_dot(a: Quat, b: DQuat) -> f64 {
    (a.as_dquat().normalize().dot(b.normalize())).abs()
}

#[test]
fn quat_from_euler_matches_scipy() {
    let data = euler_rows();
    assert!(data.len() >= 70, "{} rows", data.len());
    for order in EulerOrder::ALL {
        assert!(data.iter().filter(|(o, ..)| *o == order).count() >= 35);
    }
    let mut worst = 1.0f64;
    for (order, e, expected) in &data {
        let q = quat_from_euler(*e, *order);
        let d = abs_dot(q, *expected);
        assert!(
            d >= 1.0 - 1e-6,
            "{} {e}: ours {q} vs SciPy {expected}, |dot| = {d}",
            order.name()
        );
        worst = worst.min(d);
    }
    println!(
        "quat_from_euler vs SciPy: min |dot| = {worst:.12} (1 - {:e})",
        1.0 - worst
    );
}

#[test]
fn euler_from_quat_round_trips_the_rotation() {
    // Compare rotations, not angles: at the singularity (middle angle ±90°) the split
    // between the outer angles is arbitrary, and angles outside the principal ranges
    // come back wrapped.
    let mut worst = 1.0f64;
    for (order, e, expected) in euler_rows() {
        let q = expected.as_quat();
        let back = euler_from_quat(q, order);
        assert!(back.is_finite(), "{} {e}: {back}", order.name());
        assert!(
            back.y.abs() <= 90.0 + 1e-3
                && back.x.abs() <= 180.0 + 1e-3
                && back.z.abs() <= 180.0 + 1e-3,
            "{} {e}: {back} outside the documented ranges",
            order.name()
        );
        let again = quat_from_euler(back, order);
        let d = abs_dot(again, expected);
        assert!(
            d >= 1.0 - 1e-6,
            "{} {e}: euler_from_quat gave {back}, which is {again}, not SciPy's {expected} \
             (|dot| = {d})",
            order.name()
        );
        worst = worst.min(d);
    }
    println!(
        "euler_from_quat round trip: min |dot| = {worst:.12} (1 - {:e})",
        1.0 - worst
    );
}
