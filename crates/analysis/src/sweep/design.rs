//! Designs: which combinations of the factors' values a sweep runs, case by case. A case's
//! values are worked out from its number alone (the Latin hypercube's draws are made once, from
//! its seed), so any slice of the cases — a shard, the cases a resumed run still needs — is
//! known without listing the others.
//!
//! - *Grid*: every combination, the last factor varying fastest: `Π nᵢ` cases.
//! - *One at a time*: case 0 is the base scene; then each factor in turn through each of its
//!   levels that differs from the base, the others at the base's values: `1 + Σ (nᵢ − 1)` cases
//!   when every base value is one of the levels.
//! - *Latin hypercube* (McKay, Beckman & Conover 1979): `N` cases; each factor's range is cut
//!   into `N` strata of equal probability and each stratum is used by exactly one case:
//!   `uᵢⱼ = (πⱼ(i) + rᵢⱼ)/N` with `πⱼ` a permutation of `0…N−1` and `rᵢⱼ ∈ [0, 1)`, both drawn
//!   from the seed (ChaCha8, value-stable across platforms). A range takes `from + u (to − from)`
//!   (in logarithm for a log range); a list of levels takes level `⌊u n⌋`.
//!
//! A design's size is counted before anything of it is made, and one past the sweep's limit
//! ([`DEFAULT_MAX_CASES`] unless `--max-cases` says otherwise) is refused with its size: a
//! mistyped count is one line, not gigabytes of plan.

use super::factor::{Factor, Values};
use super::spec::{Design, Level};
use rand::seq::SliceRandom as _;
use rand::{Rng as _, SeedableRng as _};
use rand_chacha::ChaCha8Rng;

/// The most cases a sweep may have unless `tether sweep --max-cases N` says otherwise: a million
/// cases are planned in about a second and indexed in some 50 MB, and take days to run.
pub const DEFAULT_MAX_CASES: usize = 1_000_000;

/// The cases of a design.
#[derive(Debug, Clone, PartialEq)]
pub struct Cases {
    layout: Layout,
    count: usize,
}

#[derive(Debug, Clone, PartialEq)]
enum Layout {
    /// Levels per factor.
    Grid { sizes: Vec<usize> },
    /// The base's values, and each later case's change to them: (factor, level).
    OneAtATime { base: Vec<Level>, changes: Vec<(usize, Level)> },
    /// Per factor, each case's place `u ∈ [0, 1)` in its range.
    Latin { places: Vec<Vec<f64>> },
}

impl Cases {
    /// The cases `design` makes of `factors`, at most `max_cases` of them, counted before any
    /// is made.
    ///
    /// # Errors
    /// An empty design (no factor, no level, no sample), more cases than `max_cases` (with
    /// their number), a range in a design that needs levels, or (one at a time) a factor with
    /// no base value.
    pub fn new(design: &Design, factors: &[Factor], max_cases: usize) -> Result<Self, String> {
        if factors.is_empty() {
            return Err("the sweep has no factor: the design is empty".into());
        }
        match *design {
            Design::Grid => {
                let sizes =
                    factors.iter().map(|f| levels(f, "a grid").map(<[Level]>::len)).collect::<Result<Vec<_>, _>>()?;
                let count = sizes.iter().try_fold(1_usize, |n, &size| n.checked_mul(size));
                let shown: Vec<String> = sizes.iter().map(ToString::to_string).collect();
                let count = within(count, max_cases, &format!("the grid ({} levels)", shown.join(" × ")))?;
                Ok(Self { layout: Layout::Grid { sizes }, count })
            }
            Design::OneAtATime => {
                // Per factor: its levels and its value in the base scene.
                let mut around: Vec<(&[Level], Level)> = Vec::with_capacity(factors.len());
                for factor in factors {
                    let levels = levels(factor, "one at a time")?;
                    let Some(at_base) = factor.base.clone() else {
                        return Err(format!(
                            "one at a time varies each factor around the base scene's value, and the scene gives factor `{}` none (it leaves it to its default, or its paths differ): write it in the scene",
                            factor.name
                        ));
                    };
                    around.push((levels, at_base));
                }
                let count = off_base(&around).count().checked_add(1);
                let count = within(count, max_cases, "one factor at a time")?;
                let changes = off_base(&around).map(|(index, level)| (index, level.clone())).collect();
                let base = around.into_iter().map(|(_, at_base)| at_base).collect();
                Ok(Self { layout: Layout::OneAtATime { base, changes }, count })
            }
            Design::LatinHypercube { samples, seed } => {
                if samples == 0 {
                    return Err("a Latin hypercube of 0 samples is empty".into());
                }
                let count = within(usize::try_from(samples).ok(), max_cases, "the Latin hypercube")?;
                let mut random = ChaCha8Rng::seed_from_u64(seed);
                let places = factors
                    .iter()
                    .map(|_| {
                        let mut strata: Vec<usize> = (0..count).collect();
                        strata.shuffle(&mut random);
                        strata
                            .into_iter()
                            .map(|stratum| (stratum as f64 + random.random::<f64>()) / count as f64)
                            .collect()
                    })
                    .collect();
                Ok(Self { layout: Layout::Latin { places }, count })
            }
        }
    }

    /// Number of cases.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether there are none (never, once made).
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The value of each factor in case `case` (< [`Cases::len`]).
    pub fn values(&self, case: usize, factors: &[Factor]) -> Vec<Level> {
        match &self.layout {
            Layout::Grid { sizes } => {
                let mut rest = case;
                let mut picked = vec![0; sizes.len()];
                for (slot, &size) in picked.iter_mut().zip(sizes).rev() {
                    *slot = rest % size;
                    rest /= size;
                }
                factors.iter().zip(picked).map(|(factor, index)| level_at(factor, index)).collect()
            }
            Layout::OneAtATime { base, changes } => {
                let mut values = base.clone();
                if let Some((factor, level)) = case.checked_sub(1).and_then(|k| changes.get(k)) {
                    values[*factor] = level.clone();
                }
                values
            }
            Layout::Latin { places } => {
                factors.iter().zip(places).map(|(factor, places)| at_place(factor, places[case])).collect()
            }
        }
    }
}

/// `count` (`None`: past `usize`) if it is at most `max_cases`, else why not: `what`, its size,
/// and how to raise the limit.
fn within(count: Option<usize>, max_cases: usize, what: &str) -> Result<usize, String> {
    match count {
        Some(count) if count <= max_cases => Ok(count),
        Some(count) => Err(format!(
            "{what} has {count} cases, more than the limit of {max_cases}: ask for fewer, or raise the limit with --max-cases {count}"
        )),
        None => Err(format!("{what} has more than {} cases: ask for fewer", usize::MAX)),
    }
}

/// Each factor's levels that differ from its base value, with the factor's index, from its
/// `(levels, base value)` in `around`.
fn off_base<'a>(around: &'a [(&'a [Level], Level)]) -> impl Iterator<Item = (usize, &'a Level)> + 'a {
    around.iter().enumerate().flat_map(|(index, (levels, at_base))| {
        levels.iter().filter(move |level| *level != at_base).map(move |level| (index, level))
    })
}

/// A factor's levels, or why `design` cannot use it.
fn levels<'f>(factor: &'f Factor, design: &str) -> Result<&'f [Level], String> {
    match &factor.values {
        Values::Levels(levels) => Ok(levels),
        Values::Range { .. } => Err(format!(
            "factor `{}` is a range ({}), which only a Latin hypercube samples: give {design} levels (List, Linear or Log)",
            factor.name,
            factor.describe_values()
        )),
    }
}

fn level_at(factor: &Factor, index: usize) -> Level {
    match &factor.values {
        Values::Levels(levels) => levels[index].clone(),
        // Grids are made of level lists only (checked in `Cases::new`).
        Values::Range { from, .. } => Level::Number(*from),
    }
}

/// The value at place `u ∈ [0, 1]` of a factor's range or levels.
fn at_place(factor: &Factor, u: f64) -> Level {
    match &factor.values {
        Values::Levels(levels) => levels[((u * levels.len() as f64) as usize).min(levels.len() - 1)].clone(),
        Values::Range { from, to, log: false } => Level::Number(from + u * (to - from)),
        Values::Range { from, to, log: true } => Level::Number((from.ln() + u * (to.ln() - from.ln())).exp()),
    }
}
