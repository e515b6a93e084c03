//! SVG plots of a locomotion recording, to look at what the [report](crate::report)
//! measured: foot heights with the planted spans, a top-down map of the plants and the
//! root's path, and the pelvis height.
//!
//! Drawn with `plotters`' SVG backend without its `ttf` feature (which needs font-kit and
//! so fontconfig, absent on CI machines): the SVG backend writes text as `<text>`
//! elements that the viewer renders with its own fonts, and plotters only estimates their
//! size for the layout, so titles and axis labels work without any system font.
//!
//! Spaces and units: world +Z up, centimetres, seconds, as in the report.

use crate::report::{FrameRecord, Ground, PlantSpan, Report, ReportRig, Samples, Side};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// Why the plots could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// Creating the directory or writing a file failed.
    #[error("cannot write `{path}`: {source}")]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// plotters reported an error while drawing.
    #[error("cannot draw the {plot} plot: {message}")]
    Draw {
        /// Which plot.
        plot: &'static str,
        /// plotters' message.
        message: String,
    },
}

/// File name of the foot-height plot written by [`write_plots`].
pub const FOOT_HEIGHTS_SVG: &str = "foot_heights.svg";
/// File name of the top-down plant map written by [`write_plots`].
pub const FOOTPRINTS_SVG: &str = "footprints.svg";
/// File name of the pelvis-height plot written by [`write_plots`].
pub const PELVIS_HEIGHT_SVG: &str = "pelvis_height.svg";

const LEFT: RGBColor = RGBColor(31, 119, 180);
const RIGHT: RGBColor = RGBColor(214, 39, 40);
const GREY: RGBColor = RGBColor(110, 110, 110);

fn side_colour(side: Side) -> RGBColor {
    match side {
        Side::Left => LEFT,
        Side::Right => RIGHT,
    }
}

/// Writes three SVG plots into `dir` (created if missing) and returns their paths:
///
/// - [`FOOT_HEIGHTS_SVG`]: each foot's lowest contact height above the ground (cm)
///   over time (s), planted spans shaded in the foot's colour (left blue, right red),
///   the ground (0) and the ±1.5 cm grounded band marked;
/// - [`FOOTPRINTS_SVG`]: a top-down world XY map (cm, equal scale) of every plant position
///   (the foot bone at the span's first frame) and the root bone's path;
/// - [`PELVIS_HEIGHT_SVG`]: the pelvis bone's world z and its height above the ground
///   below it (cm) over time (s).
///
/// `report` supplies the numbers quoted in the titles. Missing and non-finite samples are
/// left out of the lines.
///
/// # Errors
/// The directory or a file cannot be written, or plotters fails to draw.
pub fn write_plots(
    dir: &Path,
    rig: &ReportRig,
    frames: &[FrameRecord],
    ground: &dyn Ground,
    report: &Report,
) -> Result<Vec<PathBuf>, PlotError> {
    std::fs::create_dir_all(dir).map_err(|source| PlotError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let samples = Samples::new(rig, frames, ground);
    let spans = samples.spans(rig, frames);
    let draw_err = |plot| move |message| PlotError::Draw { plot, message };
    let outputs = [
        (
            FOOT_HEIGHTS_SVG,
            foot_heights(rig, frames, &samples, &spans, report).map_err(draw_err("foot height"))?,
        ),
        (
            FOOTPRINTS_SVG,
            footprints(rig, frames, &spans, report).map_err(draw_err("footprint"))?,
        ),
        (
            PELVIS_HEIGHT_SVG,
            pelvis_height(rig, frames, ground).map_err(draw_err("pelvis height"))?,
        ),
    ];
    let mut paths = Vec::new();
    for (name, svg) in outputs {
        let path = dir.join(name);
        std::fs::write(&path, svg).map_err(|source| PlotError::Io {
            path: path.clone(),
            source,
        })?;
        paths.push(path);
    }
    Ok(paths)
}

/// Splits a sequence of optional points into runs of finite points (one polyline each).
fn polylines(points: impl Iterator<Item = Option<(f64, f64)>>) -> Vec<Vec<(f64, f64)>> {
    let mut lines = vec![Vec::new()];
    for p in points {
        match p {
            Some((x, y)) if x.is_finite() && y.is_finite() => {
                if let Some(l) = lines.last_mut() {
                    l.push((x, y));
                }
            }
            _ => {
                if lines.last().is_some_and(|l| !l.is_empty()) {
                    lines.push(Vec::new());
                }
            }
        }
    }
    lines.retain(|l| !l.is_empty());
    lines
}

/// A finite, non-empty range covering `values` and `always`, padded by 5 % and at least
/// `min_pad` on each side.
fn range(values: impl Iterator<Item = f64>, always: &[f64], min_pad: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values
        .chain(always.iter().copied())
        .filter(|v| v.is_finite())
    {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(min_pad);
    (lo - pad, hi + pad)
}

/// The recording's time span, s (unpadded: the plot starts and ends with the recording).
fn time_range(frames: &[FrameRecord]) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for t in frames.iter().map(|f| f.time).filter(|t| t.is_finite()) {
        lo = lo.min(t);
        hi = hi.max(t);
    }
    if lo > hi {
        (0.0, 1.0)
    } else if hi - lo < 1e-6 {
        (lo, lo + 1.0)
    } else {
        (lo, hi)
    }
}

type DrawResult<T> = Result<T, String>;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// A chart of these plots: an SVG with plain `f64` axes.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws each polyline as a solid line of `colour`; the first one carries the legend entry
/// `label` (the others are the same series, broken where values were missing).
fn draw_polylines<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
    lines: Vec<Vec<(f64, f64)>>,
    colour: RGBColor,
    label: &str,
) -> Result<(), String> {
    for (n, line) in lines.into_iter().enumerate() {
        let series = chart
            .draw_series(LineSeries::new(line, colour.stroke_width(2)))
            .map_err(err)?;
        if n == 0 {
            series.label(label).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
            });
        }
    }
    Ok(())
}

/// Draws the legend box at `position`.
fn draw_legend<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
    position: SeriesLabelPosition,
) -> Result<(), String> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(err)
}

fn foot_heights(
    rig: &ReportRig,
    frames: &[FrameRecord],
    samples: &Samples,
    spans: &[PlantSpan],
    report: &Report,
) -> DrawResult<String> {
    let mut svg = String::new();
    {
        let strip = 40 + 26 * u32::try_from(rig.legs.len()).unwrap_or(4).min(8);
        let root = SVGBackend::with_string(&mut svg, (1000, 480 + strip)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (top, bottom) = root.split_vertically(480);
        let heights = |leg: usize| {
            samples.frames.iter().map(move |f| {
                f.as_ref()
                    .and_then(|legs| legs.get(leg)?.lowest)
                    .map(f64::from)
            })
        };
        let all = (0..rig.legs.len()).flat_map(|l| heights(l).flatten());
        // Clip the view to a useful band: a foot lifted a metre would flatten the rest.
        let (y0, y1) = range(all.map(|h| h.clamp(-20.0, 60.0)), &[-2.0, 5.0], 0.5);
        let (x0, x1) = time_range(frames);
        let time = |t: usize| frames.get(t).map_or(f64::NAN, |f| f.time);

        // The planted spans as a timeline under the heights: one row per foot.
        let rows = rig.legs.len().max(1) as f64;
        let mut timeline = ChartBuilder::on(&bottom)
            .margin_left(12)
            .margin_right(12)
            .margin_bottom(4)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, 0.0..rows)
            .map_err(err)?;
        timeline
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_labels(0)
            .y_desc("planted")
            .draw()
            .map_err(err)?;
        for s in spans {
            let Some(leg) = rig.legs.get(s.leg) else {
                continue;
            };
            let (a, b) = (time(s.start), time(s.end));
            let row = rows - 1.0 - s.leg as f64;
            if a.is_finite() && b.is_finite() {
                timeline
                    .draw_series(std::iter::once(Rectangle::new(
                        [(a, row + 0.15), (b, row + 0.85)],
                        side_colour(leg.side).mix(0.55).filled(),
                    )))
                    .map_err(err)?;
            }
        }
        for (i, leg) in rig.legs.iter().enumerate() {
            let row = rows - 1.0 - i as f64;
            timeline
                .draw_series(std::iter::once(Text::new(
                    leg.name.clone(),
                    (x0, row + 0.5),
                    ("sans-serif", 12).into_font().color(&BLACK),
                )))
                .map_err(err)?;
        }

        let mut chart = ChartBuilder::on(&top)
            .caption(
                format!(
                    "Foot height above ground (lowest sole contact) — skate max {:.2} cm, \
                     penetration max {:.2} cm, {} steps",
                    report.skate_cm_per_stance_max, report.penetration_cm_max, report.steps
                ),
                ("sans-serif", 18),
            )
            .margin(12)
            .x_label_area_size(42)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("time (s)")
            .y_desc("height above ground (cm)")
            .x_label_formatter(&|x| format!("{x:.2}"))
            .y_label_formatter(&|y| format!("{y:.1}"))
            .draw()
            .map_err(err)?;
        // Planted spans, lightly shaded in the foot's colour (double support overlaps).
        for s in spans {
            let Some(leg) = rig.legs.get(s.leg) else {
                continue;
            };
            let (a, b) = (time(s.start), time(s.end));
            if a.is_finite() && b.is_finite() {
                chart
                    .draw_series(std::iter::once(Rectangle::new(
                        [(a, y0), (b, y1)],
                        side_colour(leg.side).mix(0.07).filled(),
                    )))
                    .map_err(err)?;
            }
        }
        let band = f64::from(crate::report::GROUNDED_TOLERANCE_CM);
        for (y, style) in [
            (0.0, BLACK.stroke_width(1)),
            (band, GREY.mix(0.6).stroke_width(1)),
            (-band, GREY.mix(0.6).stroke_width(1)),
        ] {
            chart
                .draw_series(LineSeries::new([(x0, y), (x1, y)], style))
                .map_err(err)?;
        }
        for (i, leg) in rig.legs.iter().enumerate() {
            let colour = side_colour(leg.side);
            let lines = polylines(
                frames
                    .iter()
                    .zip(heights(i))
                    .map(|(f, h)| h.map(|h| (f.time, h.clamp(y0, y1)))),
            );
            let label = format!(
                "{} ({}; shaded / bar below: planted)",
                leg.name,
                side_name(leg.side)
            );
            draw_polylines(&mut chart, lines, colour, &label)?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperRight)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::Left => "left",
        Side::Right => "right",
    }
}

fn footprints(
    rig: &ReportRig,
    frames: &[FrameRecord],
    spans: &[PlantSpan],
    report: &Report,
) -> DrawResult<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (820, 820)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let path: Vec<Option<(f64, f64)>> = frames
            .iter()
            .map(|f| {
                let p = f.world_position(rig.root)?;
                Some((f64::from(p.x), f64::from(p.y)))
            })
            .collect();
        let plants: Vec<(f64, f64, Side)> = spans
            .iter()
            .filter_map(|s| {
                let side = rig.legs.get(s.leg)?.side;
                s.position
                    .is_finite()
                    .then(|| (f64::from(s.position.x), f64::from(s.position.y), side))
            })
            .collect();
        let xs = path
            .iter()
            .flatten()
            .map(|p| p.0)
            .chain(plants.iter().map(|p| p.0));
        let ys = path
            .iter()
            .flatten()
            .map(|p| p.1)
            .chain(plants.iter().map(|p| p.1));
        let (x0, x1) = range(xs, &[], 0.5);
        let (y0, y1) = range(ys, &[], 0.5);
        // Equal scale on both axes: widen the narrower range around its centre.
        let half = ((x1 - x0).max(y1 - y0) * 0.5).max(10.0);
        let (cx, cy) = ((x0 + x1) * 0.5, (y0 + y1) * 0.5);
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!(
                    "Plants and root path, top-down — mean step length {:.1} cm, \
                     cadence {:.0} steps/min",
                    report.mean_step_length_cm, report.cadence_steps_per_min
                ),
                ("sans-serif", 17),
            )
            .margin(12)
            .x_label_area_size(42)
            .y_label_area_size(60)
            .build_cartesian_2d(cx - half..cx + half, cy - half..cy + half)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("world X (cm)")
            .y_desc("world Y (cm)")
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_label_formatter(&|y| format!("{y:.0}"))
            .draw()
            .map_err(err)?;
        draw_polylines(&mut chart, polylines(path.into_iter()), GREY, "root path")?;
        for side in [Side::Left, Side::Right] {
            let colour = side_colour(side);
            let points: Vec<(f64, f64)> = plants
                .iter()
                .filter(|p| p.2 == side)
                .map(|p| (p.0, p.1))
                .collect();
            if points.is_empty() {
                continue;
            }
            chart
                .draw_series(
                    points
                        .into_iter()
                        .map(move |p| Circle::new(p, 5, colour.filled())),
                )
                .map_err(err)?
                .label(format!("{} foot plants", side_name(side)))
                .legend(move |(x, y)| Circle::new((x + 10, y), 5, colour.filled()));
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

fn pelvis_height(
    rig: &ReportRig,
    frames: &[FrameRecord],
    ground: &dyn Ground,
) -> DrawResult<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1000, 480)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let world: Vec<Option<(f64, f64)>> = frames
            .iter()
            .map(|f| {
                let p = f.world_position(rig.pelvis)?;
                Some((f.time, f64::from(p.z)))
            })
            .collect();
        let above: Vec<Option<(f64, f64)>> = frames
            .iter()
            .map(|f| {
                let p = f.world_position(rig.pelvis)?;
                if !p.is_finite() {
                    return None;
                }
                let g = ground.ground_below(p)?;
                Some((f.time, f64::from(p.z - g)))
            })
            .collect();
        let ys = world.iter().chain(&above).flatten().map(|p| p.1);
        // At least ±2 cm around the data: a pelvis bob of a few cm stays readable.
        let (y0, y1) = range(ys, &[], 2.0);
        let (x0, x1) = time_range(frames);
        let name = rig
            .bone_names
            .get(rig.pelvis)
            .map_or("pelvis", String::as_str);
        let mut chart = ChartBuilder::on(&root)
            .caption(format!("Pelvis height (`{name}`)"), ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(42)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("time (s)")
            .y_desc("height (cm)")
            .x_label_formatter(&|x| format!("{x:.2}"))
            .y_label_formatter(&|y| format!("{y:.1}"))
            .draw()
            .map_err(err)?;
        for (n, line) in polylines(world.into_iter()).into_iter().enumerate() {
            let series = chart
                .draw_series(DashedLineSeries::new(line, 6, 4, GREY.stroke_width(2)))
                .map_err(err)?;
            if n == 0 {
                series.label("world z (cm)").legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], GREY.stroke_width(2))
                });
            }
        }
        draw_polylines(
            &mut chart,
            polylines(above.into_iter()),
            LEFT,
            "above the ground below it (cm)",
        )?;
        draw_legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}
