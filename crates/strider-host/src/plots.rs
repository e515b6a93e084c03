//! Plots of a locomotion report (SVG).
