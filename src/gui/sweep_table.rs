//! The sweep table: a sweep directory's cases, one row each — the factors' values, the status,
//! the metrics, the cost — sortable by any column (click its header; again to reverse), with
//! the failures first on request. Choosing a case (`#17`) asks the panel to load the base scene
//! with that case's values into the tuning panel, ready to run: from "case 317 diverged" to
//! watching it diverge is one click. The rows are those written so far, so a sweep still
//! running can be opened and reloaded (⟳).

use rerun::external::egui;
use std::cmp::Ordering;
use std::path::{Path, PathBuf};
use tether_analysis::sweep::case::Status;
use tether_analysis::sweep::plan::Plan;
use tether_analysis::sweep::rows::Rows;
use tether_analysis::sweep::store::Store;
use tether_analysis::sweep::table::{Columns, Row, compact};
use tether_scene::SceneFile;

/// A column of the table, by what it shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    Case,
    Factor(usize),
    Status,
    EndTime,
    Metric(usize),
    Steps,
    Cpu,
    Message,
}

/// What the table asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepAction {
    /// Load case N into the tuning panel.
    Load(usize),
}

/// An open sweep directory.
pub struct SweepTable {
    dir: PathBuf,
    plan: Plan,
    columns: Columns,
    rows: Vec<Row>,
    /// Rows in the order shown (indices into `rows`).
    order: Vec<usize>,
    sort: Option<(Column, bool)>,
    failures_first: bool,
    selected: Option<usize>,
    /// The base scene's file changed since the sweep ran.
    base_changed: bool,
}

impl SweepTable {
    /// Opens the sweep in `dir`: its manifest, its plan, the rows written so far.
    ///
    /// # Errors
    /// Not a sweep directory, or its spec, scene or rows cannot be read.
    pub fn open(dir: &Path) -> Result<Self, String> {
        let store = Store::new(dir);
        let manifest = store
            .manifest()
            .map_err(|e| e.to_string())?
            .ok_or_else(|| format!("{}: not a sweep directory (no sweep.json)", dir.display()))?;
        let plan = Plan::from_text(
            &manifest.spec_path,
            manifest.spec_text.clone(),
            Some((manifest.scene_path.clone(), manifest.scene_text.clone())),
        )
        .map_err(|e| e.to_string())?;
        let base_changed =
            std::fs::read_to_string(&manifest.scene_path).map_or(true, |text| text != manifest.scene_text);
        let mut table = Self {
            dir: dir.to_path_buf(),
            plan,
            columns: manifest.columns,
            rows: Vec::new(),
            order: Vec::new(),
            sort: None,
            failures_first: false,
            selected: None,
            base_changed,
        };
        table.reload()?;
        Ok(table)
    }

    /// Reads the rows again (a sweep still running has written more).
    ///
    /// # Errors
    /// A run file that cannot be read.
    pub fn reload(&mut self) -> Result<(), String> {
        let rows = Rows::gather(&Store::new(&self.dir), &self.columns).map_err(|e| e.to_string())?;
        let mut all = Vec::with_capacity(rows.len());
        rows.for_each(|row| {
            all.push(row);
            Ok(())
        })
        .map_err(|e| e.to_string())?;
        self.rows = all;
        self.arrange();
        Ok(())
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The sweep's name.
    pub fn name(&self) -> &str {
        &self.plan.name
    }

    /// The cases in the order shown.
    pub fn order(&self) -> Vec<usize> {
        self.order.iter().map(|&i| self.rows[i].case).collect()
    }

    /// Sorts by `column` (ascending, or descending), or restores case order.
    pub fn sort_by(&mut self, sort: Option<(Column, bool)>) {
        self.sort = sort;
        self.arrange();
    }

    /// Shows the cases that did not run to their end first.
    pub fn set_failures_first(&mut self, first: bool) {
        self.failures_first = first;
        self.arrange();
    }

    /// The base scene's path and the scene file of case `case` (the base with its values),
    /// with a note when the base scene changed since the sweep ran.
    ///
    /// # Errors
    /// No row for the case, or values the scene data does not take.
    pub fn case_scene(&self, case: usize) -> Result<(PathBuf, SceneFile, Option<String>), String> {
        let row =
            self.rows.iter().find(|r| r.case == case).ok_or_else(|| format!("the sweep has no row for case {case}"))?;
        let file = self.plan.scene_file(&row.values)?;
        let note = self.base_changed.then(|| {
            format!(
                "{} changed since the sweep ran: case {case}'s values are set on the scene as the sweep had it",
                self.plan.scene_path.display()
            )
        });
        Ok((self.plan.scene_path.clone(), file, note))
    }

    fn arrange(&mut self) {
        let mut order: Vec<usize> = (0..self.rows.len()).collect();
        let rows = &self.rows;
        let failed = |i: usize| rows[i].ending.status != Status::Ok;
        order.sort_by(|&a, &b| {
            let first = if self.failures_first { failed(b).cmp(&failed(a)) } else { Ordering::Equal };
            first.then_with(|| match self.sort {
                None => rows[a].case.cmp(&rows[b].case),
                Some((column, ascending)) => {
                    // A case without the value comes last either way.
                    let missing = |i: usize| matches!(column, Column::Metric(k) if rows[i].metrics[k].is_none());
                    let by = compare(&rows[a], &rows[b], column);
                    missing(a)
                        .cmp(&missing(b))
                        .then(if ascending { by } else { by.reverse() })
                        .then(rows[a].case.cmp(&rows[b].case))
                }
            })
        });
        self.order = order;
    }

    /// The columns shown, in order.
    fn shown(&self) -> Vec<Column> {
        let mut shown = vec![Column::Case];
        shown.extend((0..self.columns.factors.len()).map(Column::Factor));
        shown.extend([Column::Status, Column::EndTime]);
        shown.extend((0..self.columns.metrics.len()).map(Column::Metric));
        shown.extend([Column::Steps, Column::Cpu, Column::Message]);
        shown
    }

    fn title(&self, column: Column) -> String {
        match column {
            Column::Case => "case".into(),
            Column::Factor(k) => self.columns.factors[k].name.clone(),
            Column::Status => "status".into(),
            Column::EndTime => "end_time_s".into(),
            Column::Metric(k) => self.columns.metrics[k].name.clone(),
            Column::Steps => "steps".into(),
            Column::Cpu => "cpu_s".into(),
            Column::Message => "message".into(),
        }
    }

    /// Draws the table; returns what it asks for.
    pub fn ui(&mut self, ui: &mut egui::Ui) -> Option<SweepAction> {
        let mut action = None;
        let failed = self.rows.iter().filter(|r| r.ending.status != Status::Ok).count();
        ui.horizontal(|ui| {
            ui.strong(format!("Sweep {}", self.plan.name)).on_hover_text(self.dir.display().to_string());
            ui.label(format!(
                "{} of {} cases have a row, {failed} failed — choose a case (#) to load it",
                self.rows.len(),
                self.plan.cases.len()
            ));
            let mut first = self.failures_first;
            if ui.checkbox(&mut first, "failures first").changed() {
                self.set_failures_first(first);
            }
            if ui.button("⟳").on_hover_text("Read the rows again (a sweep still running has written more)").clicked()
                && let Err(error) = self.reload()
            {
                ui.colored_label(ui.visuals().error_fg_color, error);
            }
        });
        let shown = self.shown();
        let mut clicked_header: Option<Column> = None;
        egui::ScrollArea::horizontal().id_salt("sweep_table_scroll").show(ui, |ui| {
            let mut table = egui_extras::TableBuilder::new(ui)
                .id_salt("sweep_table")
                .striped(true)
                .resizable(true)
                .sense(egui::Sense::click())
                .cell_layout(egui::Layout::left_to_right(egui::Align::Center));
            for column in &shown {
                table = table.column(match column {
                    Column::Message => egui_extras::Column::remainder().at_least(200.0),
                    Column::Case => egui_extras::Column::auto().at_least(50.0),
                    _ => egui_extras::Column::auto().at_least(70.0),
                });
            }
            table
                .header(22.0, |mut header| {
                    for &column in &shown {
                        header.col(|ui| {
                            let arrow = match self.sort {
                                Some((c, true)) if c == column => " ▲",
                                Some((c, false)) if c == column => " ▼",
                                _ => "",
                            };
                            if ui
                                .button(format!("{}{arrow}", self.title(column)))
                                .on_hover_text("Sort by this column (again: the other way)")
                                .clicked()
                            {
                                clicked_header = Some(column);
                            }
                        });
                    }
                })
                .body(|body| {
                    body.rows(20.0, self.order.len(), |mut table_row| {
                        let row = &self.rows[self.order[table_row.index()]];
                        let selected = self.selected == Some(row.case);
                        table_row.set_selected(selected);
                        for &column in &shown {
                            table_row.col(|ui| {
                                if column == Column::Case {
                                    if ui
                                        .selectable_label(selected, format!("#{}", row.case))
                                        .on_hover_text("Load this case into the tuning panel")
                                        .clicked()
                                    {
                                        action = Some(SweepAction::Load(row.case));
                                    }
                                } else {
                                    cell(ui, row, column);
                                }
                            });
                        }
                        if table_row.response().clicked() {
                            action = Some(SweepAction::Load(row.case));
                        }
                    });
                });
        });
        if let Some(column) = clicked_header {
            let next = match self.sort {
                Some((c, true)) if c == column => Some((column, false)),
                Some((c, false)) if c == column => None,
                _ => Some((column, true)),
            };
            self.sort_by(next);
        }
        if let Some(SweepAction::Load(case)) = action {
            self.selected = Some(case);
        }
        action
    }
}

/// Draws one cell of `row`.
fn cell(ui: &mut egui::Ui, row: &Row, column: Column) {
    let number = |ui: &mut egui::Ui, x: Option<f64>| {
        match x {
            Some(x) => ui.label(compact(x)).on_hover_text(tether_analysis::sweep::table::number(x)),
            None => ui.weak("–"),
        };
    };
    match column {
        Column::Case => {}
        Column::Factor(k) => {
            ui.label(row.values[k].number().map_or_else(|| row.values[k].to_string(), compact));
        }
        Column::Status if row.ending.status == Status::Ok => {
            ui.label(row.ending.status.name());
        }
        Column::Status => {
            ui.colored_label(ui.visuals().error_fg_color, row.ending.status.name());
        }
        Column::EndTime => number(ui, Some(row.ending.end_time)),
        Column::Metric(k) => number(ui, row.metrics[k]),
        Column::Steps => {
            ui.label((row.ending.steps + row.ending.rejected_steps).to_string());
        }
        Column::Cpu => number(ui, Some(row.ending.cpu_seconds)),
        Column::Message => {
            ui.label(&row.ending.message).on_hover_text(&row.ending.message);
        }
    }
}

/// `a` against `b` by `column` (missing values equal: [`SweepTable::arrange`] puts them last).
fn compare(a: &Row, b: &Row, column: Column) -> Ordering {
    let numbers = |x: Option<f64>, y: Option<f64>| match (x, y) {
        (Some(x), Some(y)) => x.total_cmp(&y),
        _ => Ordering::Equal,
    };
    match column {
        Column::Case => a.case.cmp(&b.case),
        Column::Factor(k) => match (a.values[k].number(), b.values[k].number()) {
            (Some(x), Some(y)) => x.total_cmp(&y),
            _ => a.values[k].to_string().cmp(&b.values[k].to_string()),
        },
        Column::Status => a.ending.status.name().cmp(b.ending.status.name()),
        Column::EndTime => a.ending.end_time.total_cmp(&b.ending.end_time),
        Column::Metric(k) => numbers(a.metrics[k], b.metrics[k]),
        Column::Steps => (a.ending.steps + a.ending.rejected_steps).cmp(&(b.ending.steps + b.ending.rejected_steps)),
        Column::Cpu => a.ending.cpu_seconds.total_cmp(&b.ending.cpu_seconds),
        Column::Message => a.ending.message.cmp(&b.ending.message),
    }
}
