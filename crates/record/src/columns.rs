//! Arrow columns built straight from a track's flat buffers, and the chunk that carries them.
//!
//! What `rerun`'s archetype builders make (`Transform3D::with_many_translation(…)
//! .columns_of_unit_batches()` and the like), without their value-by-value serialization, which
//! cost the simulation thread about 600 instructions per pose or line and frame (callgrind, on
//! chain100) — as much as a sixth of a step. The arrays have the components' own Arrow
//! datatypes; the tests build each column both ways and compare them.

use crate::RecordError;
use crate::rerun;
use rerun::external::arrow::array::{ArrayRef, FixedSizeListArray, Float32Array, Float64Array, ListArray, UInt32Array};
use rerun::external::arrow::buffer::OffsetBuffer;
use rerun::external::arrow::datatypes::{DataType, Field};
use rerun::log::{Chunk, ChunkId, RowId, TimeColumn};
use rerun::{ComponentDescriptor, RecordingStream, SerializedComponentColumn};
use std::sync::Arc;

/// A component column: row `r` holds the next `lengths[r]` values of `values`.
pub(crate) fn column(
    descriptor: ComponentDescriptor,
    values: ArrayRef,
    lengths: impl IntoIterator<Item = usize>,
) -> SerializedComponentColumn {
    let field = Field::new_list_field(values.data_type().clone(), true);
    SerializedComponentColumn {
        list_array: ListArray::new(Arc::new(field), OffsetBuffer::from_lengths(lengths), values, None),
        descriptor,
    }
}

/// `N`-vectors of `f32` — positions, vectors, translations (`N` = 3), quaternions `[x, y, z, w]`
/// (`N` = 4) — as Rerun stores them: a fixed-size list of `N` non-null floats each.
pub(crate) fn floats<const N: usize>(values: impl IntoIterator<Item = [f32; N]>) -> ArrayRef {
    flat_floats::<N>(values.into_iter().flatten().collect())
}

/// [`floats`] from the vectors' components one after the other, `flat` moved into the column
/// without a copy (the sea surface's vertices, a chunk's largest buffer). Its callers push
/// whole `N`-vectors, so the list array's length check cannot fail.
pub(crate) fn flat_floats<const N: usize>(flat: Vec<f32>) -> ArrayRef {
    Arc::new(FixedSizeListArray::new(
        Arc::new(Field::new_list_field(DataType::Float32, false)),
        N as i32,
        Arc::new(Float32Array::from(flat)),
        None,
    ))
}

/// Line strips (Rerun's `LineStrip3D`): strip `s` holds the next `points_per_strip[s]` points.
pub(crate) fn strips(
    points: impl IntoIterator<Item = [f32; 3]>,
    points_per_strip: impl IntoIterator<Item = usize>,
) -> ArrayRef {
    let points = floats(points);
    let field = Field::new_list_field(points.data_type().clone(), false);
    Arc::new(ListArray::new(Arc::new(field), OffsetBuffer::from_lengths(points_per_strip), points, None))
}

/// A plot's column (Rerun's `Scalars`): `series` values a row, row after row.
pub(crate) fn plot(values: Vec<f64>, series: usize) -> SerializedComponentColumn {
    let rows = values.len() / series.max(1);
    column(
        rerun::Scalars::descriptor_scalars(),
        Arc::new(Float64Array::from(values)),
        std::iter::repeat_n(series, rows),
    )
}

/// Colours (Rerun's `Color`, RGBA packed in a `u32`).
pub(crate) fn colors(values: impl IntoIterator<Item = rerun::Color>) -> ArrayRef {
    Arc::new(UInt32Array::from_iter_values(values.into_iter().map(|color| color.0.0)))
}

/// Sends `columns` to entity `path` as one chunk, a row at each instant of `times`, its rows in
/// the order given (the frames' order, which is the time order: unlike
/// `RecordingStream::send_columns`, nothing is sorted again).
///
/// # Errors
/// Columns whose lengths differ from the times'.
pub(crate) fn send<const TIMELINES: usize>(
    stream: &RecordingStream,
    path: &str,
    times: [TimeColumn; TIMELINES],
    columns: Vec<SerializedComponentColumn>,
) -> Result<(), RecordError> {
    let first = RowId::new();
    let rows = times.first().map_or(0, TimeColumn::num_rows);
    let row_ids: Vec<RowId> = std::iter::successors(Some(first), |row| Some(row.next())).take(rows).collect();
    let timelines = times.into_iter().map(|time| (*time.timeline().name(), time)).collect();
    let components = columns.into_iter().map(|column| (column.descriptor, column.list_array)).collect();
    let chunk =
        Chunk::new(ChunkId::new(), path.into(), Some(true), RowId::arrow_from_slice(&row_ids), timelines, components)?;
    stream.send_chunk(chunk);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rerun::external::arrow::array::Array as _;

    /// Our columns and Rerun's builders' are the same: as many, each with the same component and
    /// the same Arrow list array.
    fn assert_same(ours: &[SerializedComponentColumn], theirs: &[SerializedComponentColumn]) {
        assert_eq!(ours.len(), theirs.len());
        for (ours, theirs) in ours.iter().zip(theirs) {
            assert_eq!(ours.descriptor, theirs.descriptor);
            assert_eq!(ours.list_array, theirs.list_array);
        }
    }

    fn translations() -> Vec<[f32; 3]> {
        (0..7).map(|i| [i as f32, -0.5 * i as f32, 1e3 + i as f32]).collect()
    }

    #[test]
    fn poses_are_what_the_transform_builder_makes() {
        let quaternions: Vec<[f32; 4]> = (0..7).map(|i| [0.1 * i as f32, 0.2, -0.3, 0.9]).collect();
        let theirs: Vec<_> = rerun::Transform3D::update_fields()
            .with_many_translation(translations())
            .with_many_quaternion(quaternions.iter().map(|&q| rerun::Quaternion::from_xyzw(q)))
            .columns_of_unit_batches()
            .expect("serializable")
            .collect();
        let ours = [
            column(rerun::Transform3D::descriptor_translation(), floats(translations()), [1; 7]),
            column(rerun::Transform3D::descriptor_quaternion(), floats(quaternions), [1; 7]),
        ];
        assert_same(&ours, &theirs);
    }

    #[test]
    fn strips_and_colours_are_what_the_line_builder_makes() {
        // Three rows of 2, 0 and 1 strips of 2, 3 and 2 points.
        let points = translations();
        let strip_lengths = [2, 3, 2];
        let rerun_strips: Vec<Vec<[f32; 3]>> =
            vec![points[0..2].to_vec(), points[2..5].to_vec(), points[5..7].to_vec()];
        let palette =
            [rerun::Color::from_rgb(1, 2, 3), rerun::Color::from_rgb(200, 100, 0), rerun::Color::from_rgb(9, 9, 9)];
        let theirs: Vec<_> = rerun::LineStrips3D::update_fields()
            .with_strips(rerun_strips)
            .with_colors(palette)
            .columns([2, 0, 1])
            .expect("serializable")
            .collect();
        let ours = [
            column(rerun::LineStrips3D::descriptor_strips(), strips(points, strip_lengths), [2, 0, 1]),
            column(rerun::LineStrips3D::descriptor_colors(), colors(palette), [2, 0, 1]),
        ];
        assert_same(&ours, &theirs);
    }

    #[test]
    fn scalars_are_what_the_scalars_builder_makes() {
        let values = vec![1.0, -2.5, 3e9, 0.0, f64::MIN_POSITIVE, 7.0];
        let theirs: Vec<_> = rerun::Scalars::new(values.clone()).columns([3, 3]).expect("serializable").collect();
        let ours = plot(values, 3);
        assert_eq!(ours.list_array.len(), 2);
        assert_same(&[ours], &theirs);
    }
}
