//! A measured record: named series of (time \[s], value) pairs, read from a CSV file, a Parquet
//! file or a Tether recording (`.rrd`, [`super::recording_input`]).
//!
//! CSV: a header row, a time column in seconds (the first, or the one the spec names), one
//! column per signal; sampling may be irregular, and an empty cell is a gap (that signal has no
//! sample at that time). Parquet: the same table, numeric columns, a null is a gap. Refused,
//! each with the file and line (CSV) or row (Parquet): a time that is not a number or does not
//! increase, a value that is not a number, NaN or infinite.

use super::series::Series;
use std::path::{Path, PathBuf};

/// Every signal of a record.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub path: PathBuf,
    pub series: Vec<Series>,
}

impl Record {
    /// Reads `path`: by its extension, `.parquet`, `.rrd`, or else CSV; `time` names the time
    /// column (CSV, Parquet; default the first).
    ///
    /// # Errors
    /// A file that cannot be read, or a value refused (above), with the file and line or row.
    pub fn read(path: &Path, time: Option<&str>) -> Result<Self, String> {
        let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let series = match extension.as_deref() {
            Some("parquet") => read_parquet(path, time)?,
            Some("rrd") => super::recording_input::read(path)?,
            _ => read_csv(path, time)?,
        };
        Ok(Self { path: path.to_path_buf(), series })
    }

    /// The series named `name`.
    ///
    /// # Errors
    /// No such series, with the names there are.
    pub fn series(&self, name: &str) -> Result<&Series, String> {
        self.series.iter().find(|s| s.name == name).ok_or_else(|| {
            let names: Vec<&str> = self.series.iter().map(|s| s.name.as_str()).collect();
            let shown = if names.len() > 12 { format!("{}, …", names[..12].join(", ")) } else { names.join(", ") };
            format!("{} has no column \"{name}\" (columns: {shown})", self.path.display())
        })
    }
}

fn read_csv(path: &Path, time: Option<&str>) -> Result<Vec<Series>, String> {
    let at = |line: u64, message: String| format!("{}:{line}: {message}", path.display());
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_path(path)
        .map_err(|e| format!("{}: cannot read the record: {e}", path.display()))?;
    let headers = reader.headers().map_err(|e| at(1, format!("cannot read the header row: {e}")))?.clone();
    let time_index = time_column(headers.iter(), time).map_err(|m| at(1, m))?;
    let mut series: Vec<Series> = headers
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != time_index)
        .map(|(_, name)| Series { name: name.to_string(), times: Vec::new(), values: Vec::new() })
        .collect();
    let mut last_time = f64::NEG_INFINITY;
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(0, csv::Position::line);
            at(line, format!("cannot read the row: {e}"))
        })?;
        // Every record read from a file has a position.
        let line = record.position().map_or(0, csv::Position::line);
        let time_text = record.get(time_index).unwrap_or("");
        let t = number(time_text).map_err(|m| at(line, format!("time \"{time_text}\": {m}")))?;
        if t <= last_time {
            return Err(at(line, format!("time {t} s does not increase (the row before is at {last_time} s)")));
        }
        last_time = t;
        let cells = record.iter().enumerate().filter(|(i, _)| *i != time_index);
        for ((_, cell), series) in cells.zip(&mut series) {
            if cell.is_empty() {
                continue;
            }
            let value = number(cell).map_err(|m| at(line, format!("column \"{}\" \"{cell}\": {m}", series.name)))?;
            series.times.push(t);
            series.values.push(value);
        }
    }
    Ok(series)
}

/// A finite number.
fn number(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err("not a finite number (NaN and infinities are refused; leave the cell empty for a gap)".into()),
        Err(_) => Err("not a number".into()),
    }
}

/// The index of the time column among `names`: `wanted`, or the first.
fn time_column<'a>(names: impl Iterator<Item = &'a str>, wanted: Option<&str>) -> Result<usize, String> {
    let names: Vec<&str> = names.collect();
    if names.len() < 2 {
        return Err(format!(
            "the header has {} column(s): a time column and at least one signal are needed",
            names.len()
        ));
    }
    match wanted {
        None => Ok(0),
        Some(wanted) => names
            .iter()
            .position(|n| *n == wanted)
            .ok_or_else(|| format!("no time column \"{wanted}\" (columns: {})", names.join(", "))),
    }
}

fn read_parquet(path: &Path, time: Option<&str>) -> Result<Vec<Series>, String> {
    use arrow_array::Array;
    use arrow_array::cast::AsArray;
    use arrow_array::types::Float64Type;
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
    let fail = |m: String| format!("{}: {m}", path.display());
    let file = std::fs::File::open(path).map_err(|e| fail(format!("cannot read the record: {e}")))?;
    let builder =
        ParquetRecordBatchReaderBuilder::try_new(file).map_err(|e| fail(format!("not a Parquet file: {e}")))?;
    let schema = builder.schema().clone();
    let names: Vec<&str> = schema.fields().iter().map(|f| f.name().as_str()).collect();
    let time_index = time_column(names.iter().copied(), time).map_err(fail)?;
    let mut series: Vec<Series> = names
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != time_index)
        .map(|(_, name)| Series { name: (*name).to_string(), times: Vec::new(), values: Vec::new() })
        .collect();
    let reader = builder.build().map_err(|e| fail(format!("cannot read: {e}")))?;
    let mut row = 0usize;
    let mut last_time = f64::NEG_INFINITY;
    for batch in reader {
        let batch = batch.map_err(|e| fail(format!("cannot read: {e}")))?;
        let columns: Vec<arrow_array::ArrayRef> = batch
            .columns()
            .iter()
            .zip(&names)
            .map(|(column, name)| arrow_cast_f64(column).map_err(|m| fail(format!("column \"{name}\": {m}"))))
            .collect::<Result<_, _>>()?;
        let time_column = columns[time_index].as_primitive::<Float64Type>();
        for i in 0..batch.num_rows() {
            row += 1;
            if time_column.is_null(i) {
                return Err(fail(format!("row {row}: the time is empty")));
            }
            let t = time_column.value(i);
            if !t.is_finite() || t <= last_time {
                return Err(fail(format!(
                    "row {row}: time {t} s is not finite or does not increase (the row before is at {last_time} s)"
                )));
            }
            last_time = t;
            let others = columns.iter().enumerate().filter(|(c, _)| *c != time_index);
            for ((_, column), series) in others.zip(&mut series) {
                let column = column.as_primitive::<Float64Type>();
                if column.is_null(i) {
                    continue;
                }
                let value = column.value(i);
                if !value.is_finite() {
                    return Err(fail(format!(
                        "row {row}: column \"{}\" is {value} (leave it null for a gap)",
                        series.name
                    )));
                }
                series.times.push(t);
                series.values.push(value);
            }
        }
    }
    Ok(series)
}

/// A numeric column as `Float64`.
fn arrow_cast_f64(column: &arrow_array::ArrayRef) -> Result<arrow_array::ArrayRef, String> {
    use arrow_array::Float64Array;
    use arrow_array::cast::AsArray;
    use arrow_array::types::{Float32Type, Int32Type, Int64Type};
    use arrow_schema::DataType;
    let as_f64 =
        |values: Vec<Option<f64>>| -> arrow_array::ArrayRef { std::sync::Arc::new(Float64Array::from(values)) };
    Ok(match column.data_type() {
        DataType::Float64 => column.clone(),
        DataType::Float32 => as_f64(column.as_primitive::<Float32Type>().iter().map(|v| v.map(f64::from)).collect()),
        DataType::Int64 => as_f64(column.as_primitive::<Int64Type>().iter().map(|v| v.map(|x| x as f64)).collect()),
        DataType::Int32 => as_f64(column.as_primitive::<Int32Type>().iter().map(|v| v.map(f64::from)).collect()),
        other => return Err(format!("is {other}, not a number")),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn csv_file(text: &str) -> tempfile::NamedTempFile {
        use std::io::Write;
        let mut file = tempfile::Builder::new().suffix(".csv").tempfile().unwrap();
        file.write_all(text.as_bytes()).unwrap();
        file
    }

    #[test]
    fn gaps_and_irregular_times() {
        let file = csv_file("t,x,F\n0.0,1.0,10\n0.1,,11\n0.25,1.5,\n");
        let record = Record::read(file.path(), None).unwrap();
        let x = record.series("x").unwrap();
        assert_eq!(x.times, vec![0.0, 0.25]);
        assert_eq!(x.values, vec![1.0, 1.5]);
        assert_eq!(record.series("F").unwrap().times, vec![0.0, 0.1]);
        let missing = record.series("y").unwrap_err();
        assert!(missing.contains("no column \"y\"") && missing.contains("x, F"), "{missing}");
    }

    /// A Parquet table: float and integer columns, a null as a gap, NaN refused with its row.
    #[test]
    fn parquet_columns_with_a_gap() {
        use arrow_array::{Float64Array, Int64Array, RecordBatch};
        use std::sync::Arc;
        let write = |x: Vec<Option<f64>>| {
            let file = tempfile::Builder::new().suffix(".parquet").tempfile().unwrap();
            let batch = RecordBatch::try_from_iter([
                ("t", Arc::new(Float64Array::from(vec![0.0, 0.5, 1.0])) as arrow_array::ArrayRef),
                ("x", Arc::new(Float64Array::from(x)) as arrow_array::ArrayRef),
                ("n", Arc::new(Int64Array::from(vec![1, 2, 3])) as arrow_array::ArrayRef),
            ])
            .unwrap();
            let mut writer =
                parquet::arrow::ArrowWriter::try_new(file.reopen().unwrap(), batch.schema(), None).unwrap();
            writer.write(&batch).unwrap();
            writer.close().unwrap();
            file
        };
        let file = write(vec![Some(1.0), None, Some(3.0)]);
        let record = Record::read(file.path(), None).unwrap();
        assert_eq!(record.series("x").unwrap().times, vec![0.0, 1.0]);
        assert_eq!(record.series("n").unwrap().values, vec![1.0, 2.0, 3.0]);
        let nan = write(vec![Some(1.0), Some(f64::NAN), Some(3.0)]);
        let error = Record::read(nan.path(), None).unwrap_err();
        assert!(error.contains("row 2") && error.contains("\"x\""), "{error}");
    }

    #[test]
    fn bad_values_are_placed() {
        let nan = csv_file("t,x\n0.0,1.0\n0.1,NaN\n");
        let error = Record::read(nan.path(), None).unwrap_err();
        assert!(error.contains(":3:") && error.contains("not a finite number"), "{error}");
        let backwards = csv_file("t,x\n0.0,1.0\n0.2,1.0\n0.1,1.0\n");
        let error = Record::read(backwards.path(), None).unwrap_err();
        assert!(error.contains(":4:") && error.contains("does not increase"), "{error}");
        let short = csv_file("t,x\n0.0,1.0\n0.1\n");
        let error = Record::read(short.path(), None).unwrap_err();
        assert!(error.contains(":3:") && error.contains("cannot read the row"), "{error}");
        let text = csv_file("t,x\n0.0,one\n");
        let error = Record::read(text.path(), None).unwrap_err();
        assert!(error.contains(":2:") && error.contains("not a number"), "{error}");
        let named = csv_file("x,time\n1.0,0.0\n");
        assert_eq!(Record::read(named.path(), Some("time")).unwrap().series("x").unwrap().times, vec![0.0]);
        assert!(Record::read(named.path(), Some("clock")).unwrap_err().contains("no time column \"clock\""));
    }
}
