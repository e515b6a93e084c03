//! Curves through control points: Control Rig's "Spline From Points" + "Position From
//! Spline", as used by the locomotion rig's foot swing arc (`CalculateFootSpline`).
//!
//! [`evaluate`] takes the control points as a slice and returns the position and tangent at
//! a parameter `U ∈ [0, 1]`. It allocates nothing (de Boor runs on a fixed-size stack
//! array) and never panics: any number of points, any `u` (clamped; NaN → 0) and
//! non-finite points are accepted. Non-finite points give whatever the arithmetic gives
//! (typically NaN or infinite components); no attempt is made to clean them up.

use glam::Vec3;

/// Highest B-spline degree: cubic.
const MAX_DEGREE: usize = 3;

/// Which curve to build through the control points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineMode {
    /// Clamped uniform B-spline of degree `min(3, N − 1)`: starts at the first point, ends
    /// at the last, and is pulled towards (not through) the points in between.
    BSpline,
    /// Uniform Catmull-Rom curve through every point (one cubic segment per pair of
    /// neighbouring points, end tangents from duplicated end points).
    CatmullRom,
}

/// Position and tangent (derivative with respect to U, cm per unit U) at parameter `u`
/// (clamped to [0, 1]; NaN → 0) on the curve through `points` built as `mode` says.
///
/// **[`SplineMode::BSpline`]**: the clamped uniform B-spline of degree
/// `k = min(3, N − 1)` over the `N` points. Its knot vector has `k + 1` zeros, the uniform
/// interior knots `1/(N−k), 2/(N−k), …, (N−k−1)/(N−k)` and `k + 1` ones, so it has
/// `N − k` spans of equal width. **U is the knot parameter itself** (U maps linearly,
/// identity, onto the knot domain [0, 1]): U = 0 is the first point, U = 1 the last point,
/// and span `j` covers `U ∈ [j/(N−k), (j+1)/(N−k)]`. U is not arc length: the speed along
/// the curve varies. With 2 points this is the straight segment, with 3 the quadratic
/// Bézier, with 4 the cubic Bézier. Evaluated with de Boor's algorithm; the tangent is
/// `k·(N−k)` times the difference of the last two de Boor points.
///
/// **[`SplineMode::CatmullRom`]**: the uniform (not centripetal) Catmull-Rom curve. U is
/// split evenly across the `N − 1` segments: segment `i` (from point `i` to point `i + 1`)
/// covers `U ∈ [i/(N−1), (i+1)/(N−1)]`, so the curve passes through point `i` at
/// `U = i/(N−1)`. Inner tangents are `(P[i+1] − P[i−1]) / 2` per segment; at the ends the
/// missing neighbour is the end point itself (duplicated), giving `(P[1] − P[0]) / 2` and
/// `(P[N−1] − P[N−2]) / 2`. With 2 points it is the straight segment, parameterised
/// linearly like the B-spline.
///
/// Degenerate input: no points → `(0, 0)`; one point → `(that point, 0)`. Points that are
/// not finite give whatever the arithmetic gives (NaN/∞ components), never a panic.
#[must_use]
pub fn evaluate(points: &[Vec3], u: f32, mode: SplineMode) -> (Vec3, Vec3) {
    let u = if u.is_nan() { 0.0 } else { u.clamp(0.0, 1.0) };
    match points {
        [] => (Vec3::ZERO, Vec3::ZERO),
        [point] => (*point, Vec3::ZERO),
        _ => match mode {
            SplineMode::BSpline => bspline(points, u),
            SplineMode::CatmullRom => catmull_rom(points, u),
        },
    }
}

/// Splits `u ∈ [0, 1]` over `count ≥ 1` equal pieces: the piece index and the local
/// parameter in [0, 1] (U = 1 is the end of the last piece).
fn split(u: f32, count: usize) -> (usize, f32) {
    let x = u * count as f32;
    // `as` floors non-negative values and saturates; never past the last piece.
    let piece = (x as usize).min(count - 1);
    (piece, (x - piece as f32).clamp(0.0, 1.0))
}

/// de Boor on the clamped uniform knot vector, for `points.len() ≥ 2`.
///
/// Works in span units: the knot with index `i` sits at `clamp(i − k, 0, N − k)` spans, and
/// everything is taken relative to the start of the current span so the numbers stay small
/// whatever N is.
fn bspline(points: &[Vec3], u: f32) -> (Vec3, Vec3) {
    let n = points.len();
    let k = (n - 1).min(MAX_DEGREE);
    let spans = n - k;
    let (span, t) = split(u, spans);
    // Knot index `index` relative to the start of `span` (whose knot index is `span + k`).
    let knot = |index: usize| -> f32 {
        let at = (index as isize - k as isize).clamp(0, spans as isize);
        (at - span as isize) as f32
    };
    // The k + 1 control points that influence this span: span ..= span + k (≤ N − 1).
    let mut d = [Vec3::ZERO; MAX_DEGREE + 1];
    for (slot, point) in d.iter_mut().zip(&points[span..=span + k]) {
        *slot = *point;
    }
    let mut tangent = Vec3::ZERO;
    for r in 1..=k {
        if r == k {
            // d[k−1], d[k] are now the end points of the last (linear) step over one span:
            // dP/dx = k·(d[k] − d[k−1]) / 1 span, and x = U·(N − k).
            tangent = (d[k] - d[k - 1]) * (k * spans) as f32;
        }
        for j in (r..=k).rev() {
            let i = span + j;
            let lo = knot(i);
            let hi = knot(i + k + 1 - r);
            // hi − lo ≥ 1 for every i here (the knot interval contains the current span).
            let alpha = (t - lo) / (hi - lo);
            d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
        }
    }
    (d[k], tangent)
}

/// Uniform Catmull-Rom with duplicated end points, for `points.len() ≥ 2`.
fn catmull_rom(points: &[Vec3], u: f32) -> (Vec3, Vec3) {
    let n = points.len();
    let segments = n - 1;
    if segments == 1 {
        // Two points: the straight segment at constant speed.
        let (a, b) = (points[0], points[1]);
        return (a * (1.0 - u) + b * u, b - a);
    }
    let (seg, t) = split(u, segments);
    let p1 = points[seg];
    let p2 = points[seg + 1];
    let p0 = if seg == 0 { p1 } else { points[seg - 1] };
    let p3 = points.get(seg + 2).copied().unwrap_or(p2);
    let m1 = (p2 - p0) * 0.5;
    let m2 = (p3 - p1) * 0.5;
    // Cubic Hermite basis and its derivative.
    let t2 = t * t;
    let t3 = t2 * t;
    let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    let h10 = t3 - 2.0 * t2 + t;
    let h01 = -2.0 * t3 + 3.0 * t2;
    let h11 = t3 - t2;
    let position = p1 * h00 + m1 * h10 + p2 * h01 + m2 * h11;
    let d00 = 6.0 * t2 - 6.0 * t;
    let d10 = 3.0 * t2 - 4.0 * t + 1.0;
    let d01 = -d00;
    let d11 = 3.0 * t2 - 2.0 * t;
    let tangent = (p1 * d00 + m1 * d10 + p2 * d01 + m2 * d11) * segments as f32;
    (position, tangent)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MODES: [SplineMode; 2] = [SplineMode::BSpline, SplineMode::CatmullRom];

    fn near(a: Vec3, b: Vec3, tol: f32) -> bool {
        (a - b).length() <= tol
    }

    #[track_caller]
    fn assert_near(a: Vec3, b: Vec3, tol: f32) {
        assert!(near(a, b, tol), "{a} != {b}");
    }

    /// The 7-point foot swing of the locomotion rig (cm): start, behind, lifted, mid,
    /// lifted, ahead, end.
    fn swing() -> [Vec3; 7] {
        [
            Vec3::new(10.0, -30.0, 0.0),
            Vec3::new(10.0, -34.0, 0.0),
            Vec3::new(10.0, -34.0, 6.0),
            Vec3::new(11.0, 0.0, 9.0),
            Vec3::new(10.0, 40.0, 12.0),
            Vec3::new(10.0, 40.0, 0.0),
            Vec3::new(10.0, 30.0, 0.0),
        ]
    }

    #[test]
    fn two_points_are_the_straight_segment() {
        let p0 = Vec3::new(1.0, 2.0, 3.0);
        let p1 = Vec3::new(5.0, -2.0, 11.0);
        for mode in MODES {
            let (p, t) = evaluate(&[p0, p1], 0.25, mode);
            assert_near(p, p0 * 0.75 + p1 * 0.25, 1e-6);
            assert_near(t, p1 - p0, 1e-5);
            assert_eq!(evaluate(&[p0, p1], 0.0, mode).0, p0);
            assert_eq!(evaluate(&[p0, p1], 1.0, mode).0, p1);
        }
    }

    #[test]
    fn three_points_are_the_quadratic_bezier() {
        let [p0, p1, p2] = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(4.0, 8.0, -2.0),
            Vec3::new(10.0, 2.0, 6.0),
        ];
        for i in 0..=20 {
            let u = i as f32 / 20.0;
            let (p, t) = evaluate(&[p0, p1, p2], u, SplineMode::BSpline);
            let v = 1.0 - u;
            let expected = p0 * (v * v) + p1 * (2.0 * u * v) + p2 * (u * u);
            // d/du: 2(1−u)(p1 − p0) + 2u(p2 − p1).
            let derivative = (p1 - p0) * (2.0 * v) + (p2 - p1) * (2.0 * u);
            assert_near(p, expected, 1e-5);
            assert_near(t, derivative, 1e-4);
        }
    }

    #[test]
    fn four_points_are_the_cubic_bezier() {
        let [p0, p1, p2, p3] = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(0.0, 10.0, 15.0),
            Vec3::new(5.0, 30.0, 15.0),
            Vec3::new(5.0, 40.0, 0.0),
        ];
        for i in 0..=20 {
            let u = i as f32 / 20.0;
            let (p, t) = evaluate(&[p0, p1, p2, p3], u, SplineMode::BSpline);
            let v = 1.0 - u;
            let expected = p0 * (v * v * v)
                + p1 * (3.0 * u * v * v)
                + p2 * (3.0 * u * u * v)
                + p3 * (u * u * u);
            // d/du: 3(1−u)²(p1 − p0) + 6u(1−u)(p2 − p1) + 3u²(p3 − p2).
            let derivative =
                (p1 - p0) * (3.0 * v * v) + (p2 - p1) * (6.0 * u * v) + (p3 - p2) * (3.0 * u * u);
            assert_near(p, expected, 1e-4);
            assert_near(t, derivative, 1e-3);
        }
    }

    #[test]
    fn bspline_interpolates_the_end_points_and_their_tangents() {
        let pts = swing();
        let (start, t0) = evaluate(&pts, 0.0, SplineMode::BSpline);
        let (end, t1) = evaluate(&pts, 1.0, SplineMode::BSpline);
        assert_eq!(start, pts[0]);
        assert_eq!(end, pts[6]);
        // Clamped cubic with 4 spans: the end tangent is 3·4·(P1 − P0) = 12·(P1 − P0).
        assert_near(t0, (pts[1] - pts[0]) * 12.0, 1e-4);
        assert_near(t1, (pts[6] - pts[5]) * 12.0, 1e-4);
    }

    #[test]
    fn bspline_is_continuous_across_knots() {
        // The 7-point cubic has interior knots at 1/4, 1/2, 3/4: evaluating just either side
        // of each must agree in position and tangent (C² spline).
        let pts = swing();
        for knot in [0.25f32, 0.5, 0.75] {
            let (a, ta) = evaluate(&pts, knot - 1e-4, SplineMode::BSpline);
            let (b, tb) = evaluate(&pts, knot + 1e-4, SplineMode::BSpline);
            assert_near(a, b, 0.05);
            assert_near(ta, tb, 0.5);
        }
    }

    #[test]
    fn tangent_is_the_derivative() {
        // Central differences agree with the analytic tangent away from segment joins.
        let pts = swing();
        for mode in MODES {
            for i in 1..40 {
                let u = (i as f32 + 0.37) / 41.0;
                let h = 1e-3;
                let fd =
                    (evaluate(&pts, u + h, mode).0 - evaluate(&pts, u - h, mode).0) / (2.0 * h);
                let (_, t) = evaluate(&pts, u, mode);
                assert!(
                    near(t, fd, 0.05 * t.length().max(1.0)),
                    "{mode:?} u={u}: {t} vs {fd}"
                );
            }
        }
    }

    #[test]
    fn catmull_rom_passes_through_every_point() {
        for n in 3..=9 {
            let pts: Vec<Vec3> = (0..n)
                .map(|i| Vec3::new(i as f32 * 3.0, ((i * 7) % 5) as f32, (i * i) as f32))
                .collect();
            for (i, p) in pts.iter().enumerate() {
                let u = i as f32 / (n - 1) as f32;
                assert_near(evaluate(&pts, u, SplineMode::CatmullRom).0, *p, 1e-4);
            }
        }
        // Inner tangent: (P[i+1] − P[i−1])/2 per segment, × (N − 1) segments per unit U.
        let pts = swing();
        let (_, t) = evaluate(&pts, 3.0 / 6.0, SplineMode::CatmullRom);
        assert_near(t, (pts[4] - pts[2]) * 0.5 * 6.0, 1e-3);
        // End tangents from duplicated end points: (P1 − P0)/2 × 6.
        let (_, t) = evaluate(&pts, 0.0, SplineMode::CatmullRom);
        assert_near(t, (pts[1] - pts[0]) * 3.0, 1e-4);
        let (_, t) = evaluate(&pts, 1.0, SplineMode::CatmullRom);
        assert_near(t, (pts[6] - pts[5]) * 3.0, 1e-4);
    }

    #[test]
    fn degenerate_inputs() {
        for mode in MODES {
            assert_eq!(evaluate(&[], 0.5, mode), (Vec3::ZERO, Vec3::ZERO));
            let p = Vec3::new(1.0, -2.0, 3.0);
            assert_eq!(evaluate(&[p], 0.5, mode), (p, Vec3::ZERO));
            assert_eq!(evaluate(&[p], f32::NAN, mode), (p, Vec3::ZERO));
            // All points equal: the point, not moving.
            for n in 2..=8 {
                let pts = vec![p; n];
                for u in [0.0, 0.3, 0.5, 1.0] {
                    let (pos, t) = evaluate(&pts, u, mode);
                    assert_near(pos, p, 1e-5);
                    assert_near(t, Vec3::ZERO, 1e-4);
                }
            }
            // u outside [0, 1] is clamped; NaN counts as 0.
            let pts = swing();
            assert_eq!(evaluate(&pts, -3.0, mode), evaluate(&pts, 0.0, mode));
            assert_eq!(evaluate(&pts, 7.0, mode), evaluate(&pts, 1.0, mode));
            assert_eq!(
                evaluate(&pts, f32::INFINITY, mode),
                evaluate(&pts, 1.0, mode)
            );
            assert_eq!(
                evaluate(&pts, f32::NEG_INFINITY, mode),
                evaluate(&pts, 0.0, mode)
            );
            assert_eq!(evaluate(&pts, f32::NAN, mode), evaluate(&pts, 0.0, mode));
        }
    }

    #[test]
    fn never_panics() {
        let us = [
            0.0,
            f32::MIN_POSITIVE,
            1e-7,
            0.25,
            0.5,
            1.0 - f32::EPSILON,
            1.0 - f32::EPSILON / 2.0,
            1.0,
            f32::NAN,
            f32::INFINITY,
            -0.0,
        ];
        let weird = [
            Vec3::new(f32::NAN, 0.0, 1.0),
            Vec3::new(f32::INFINITY, f32::NEG_INFINITY, 0.0),
            Vec3::splat(f32::MAX),
            Vec3::splat(-f32::MAX),
        ];
        for n in 0..40 {
            let pts: Vec<Vec3> = (0..n)
                .map(|i| {
                    if i % 7 == 3 {
                        weird[i % 4]
                    } else {
                        Vec3::splat(i as f32)
                    }
                })
                .collect();
            for mode in MODES {
                for u in us {
                    let _ = evaluate(&pts, u, mode);
                }
                for i in 0..=1000 {
                    let _ = evaluate(&pts, i as f32 / 1000.0, mode);
                }
            }
        }
        // Many points: the span lookup stays in range.
        let pts: Vec<Vec3> = (0..100_000)
            .map(|i| Vec3::new(i as f32, 0.0, 0.0))
            .collect();
        for mode in MODES {
            for u in us {
                let _ = evaluate(&pts, u, mode);
            }
            assert_eq!(evaluate(&pts, 1.0, mode).0, pts[pts.len() - 1]);
        }
    }
}
