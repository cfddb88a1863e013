//! `summary.md`: what was swept and what came out — the factors and the design, how many cases
//! ended how, each metric's range over the cases that ran to their end (with the case at each
//! extreme), the failures with their messages, and the charts. Gathered row by row in case
//! order, so it holds a few numbers per metric however many cases there are.

use super::case::Status;
use super::plan::Plan;
use super::table::{Columns, Row, compact};
use std::fmt::Write as _;

/// Failures listed in full; the rest are counted.
const LISTED_FAILURES: usize = 20;

/// A metric's extremes over the ok cases.
#[derive(Debug, Clone, Copy, Default)]
struct Extremes {
    min: Option<(f64, usize)>,
    max: Option<(f64, usize)>,
    sum: f64,
    count: usize,
}

/// The summary, gathered row by row.
pub struct Summary {
    columns: Columns,
    cases: usize,
    statuses: [usize; Status::ALL.len()],
    extremes: Vec<Extremes>,
    failures: Vec<(usize, Status, String)>,
    cpu_seconds: f64,
}

impl Summary {
    pub fn new(columns: &Columns) -> Self {
        Self {
            columns: columns.clone(),
            cases: 0,
            statuses: [0; Status::ALL.len()],
            extremes: vec![Extremes::default(); columns.metrics.len()],
            failures: Vec::new(),
            cpu_seconds: 0.0,
        }
    }

    /// Takes one row (rows come in case order, so ties go to the lowest case).
    pub fn add(&mut self, row: &Row) {
        self.cases += 1;
        self.cpu_seconds += row.ending.cpu_seconds;
        if let Some(slot) = Status::ALL.iter().position(|s| *s == row.ending.status) {
            self.statuses[slot] += 1;
        }
        if row.ending.status != Status::Ok && self.failures.len() < LISTED_FAILURES {
            self.failures.push((row.case, row.ending.status, row.ending.message.clone()));
        }
        for (extremes, value) in self.extremes.iter_mut().zip(&row.metrics) {
            let Some(x) = *value else { continue };
            if extremes.min.is_none_or(|(min, _)| x < min) {
                extremes.min = Some((x, row.case));
            }
            if extremes.max.is_none_or(|(max, _)| x > max) {
                extremes.max = Some((x, row.case));
            }
            extremes.sum += x;
            extremes.count += 1;
        }
    }

    /// `38 ok, 2 diverged`.
    pub fn statuses(&self) -> String {
        let parts: Vec<String> = Status::ALL
            .iter()
            .zip(self.statuses)
            .filter(|(_, n)| *n > 0)
            .map(|(s, n)| format!("{n} {}", s.name()))
            .collect();
        parts.join(", ")
    }

    /// The Markdown text, for the sweep `plan` whose charts are `charts` (paths relative to
    /// the summary).
    pub fn markdown(&self, plan: &Plan, charts: &[String]) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "# Sweep {}\n", plan.name);
        let absolute = |p: &std::path::Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
        let _ = writeln!(
            out,
            "Spec `{}`, base scene `{}`; design: {}, {} cases.\n",
            absolute(&plan.spec_path).display(),
            absolute(&plan.scene_path).display(),
            plan.design.describe(),
            plan.cases.len()
        );
        out.push_str("| factor | sets | values | base scene |\n|---|---|---|---|\n");
        for factor in &plan.factors {
            let base = factor.base.as_ref().map_or_else(|| "(default)".to_string(), ToString::to_string);
            let _ = writeln!(
                out,
                "| `{}` | `{}` | {} | {base} |",
                factor.name,
                factor.describe_paths(),
                factor.describe_values()
            );
        }
        let _ = writeln!(
            out,
            "\n**Cases:** {} — {}. CPU time of the runs: {:.3} s.\n",
            self.cases,
            self.statuses(),
            self.cpu_seconds
        );
        out.push_str("Every value in full precision, with every case's row: `results.csv`, `results.parquet`.\n\n");
        out.push_str("## Metrics\n\nOver the cases that ran to their end (a failed case has no metrics).\n\n");
        out.push_str("| metric | unit | min | at case | max | at case | mean |\n|---|---|---|---|---|---|---|\n");
        for (column, extremes) in self.columns.metrics.iter().zip(&self.extremes) {
            let cell = |extreme: Option<(f64, usize)>| {
                extreme.map_or_else(|| "– | –".to_string(), |(x, case)| format!("{} | {case}", compact(x)))
            };
            let mean = if extremes.count > 0 { compact(extremes.sum / extremes.count as f64) } else { "–".into() };
            let _ = writeln!(
                out,
                "| `{}` | {} | {} | {} | {mean} |",
                column.name,
                column.unit,
                cell(extremes.min),
                cell(extremes.max)
            );
        }
        let failed = self.cases - self.statuses[0];
        if failed > 0 {
            let _ = writeln!(
                out,
                "\n## Failures\n\n{failed} cases did not run to their end{}.\n",
                if failed > self.failures.len() {
                    format!(" (the first {} listed; all are in results.csv)", self.failures.len())
                } else {
                    String::new()
                }
            );
            out.push_str("| case | values | status | message |\n|---|---|---|---|\n");
            for (case, status, message) in &self.failures {
                let _ = writeln!(
                    out,
                    "| {case} | {} | {} | {} |",
                    plan.describe(*case),
                    status.name(),
                    message.replace('|', "\\|")
                );
            }
        }
        if !charts.is_empty() {
            let _ = writeln!(out, "\n## Charts\n\nEach metric against each factor (`plots/`):\n");
            for chart in charts {
                let _ = writeln!(out, "- [{chart}]({chart})");
            }
        }
        out
    }
}
