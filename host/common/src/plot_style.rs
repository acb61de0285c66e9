//! The look every plot of the workspace shares (`bearing shaft`, `bearing ehl`, `bearing
//! film`, `hil-sim replay`): one legend style, so the figures read alike.

use plotters::chart::{ChartContext, SeriesLabelPosition};
use plotters::coord::CoordTranslate;
use plotters::drawing::DrawingAreaErrorKind;
use plotters::prelude::{DrawingBackend, BLACK, WHITE};
use plotters::style::Color;

/// Draw the legend of `chart`'s labelled series at `position`: a white, slightly translucent
/// box with a black border.
pub fn draw_legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
}
