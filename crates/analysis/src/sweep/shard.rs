//! Shards: the I-th of N disjoint slices of a sweep's cases, one per job of a cluster's job
//! array — case `c` belongs to shard `c mod N`, so each shard gets every N-th case and the
//! shards' loads match however the design orders its cases.
//!
//! The shard comes from `--shard I/N`, or from the scheduler: a Slurm job array's
//! `SLURM_ARRAY_TASK_ID` (counted from `SLURM_ARRAY_TASK_MIN` in steps of
//! `SLURM_ARRAY_TASK_STEP`) and `SLURM_ARRAY_TASK_COUNT`, or a Kubernetes indexed job's
//! `JOB_COMPLETION_INDEX` with the count given as `--shard auto/N` (Kubernetes does not put the
//! job's completions in the environment).

/// The `index`-th of `count` slices.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

/// What `--shard` asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShardArg {
    /// `I/N`.
    Given(Shard),
    /// `auto` or `auto/N`: the index (and the count, without N) from the scheduler.
    Auto { count: Option<u32> },
}

impl Shard {
    /// Whether case `case` is in this shard.
    pub fn contains(&self, case: usize) -> bool {
        case % self.count as usize == self.index as usize
    }

    /// The file its rows go to: `shard-2-of-4.csv`.
    pub fn file_name(&self) -> String {
        format!("shard-{}-of-{}.csv", self.index, self.count)
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// Reads `I/N`, `auto` or `auto/N` (the command line's `--shard`).
///
/// # Errors
/// Anything else, or an index not below the count.
pub fn parse(text: &str) -> Result<ShardArg, String> {
    let count = |n: &str| match n.parse::<u32>() {
        Ok(0) => Err("the number of shards must be at least 1".to_string()),
        Ok(n) => Ok(n),
        Err(_) => Err(format!("`{n}` is not a number of shards")),
    };
    match text.split_once('/') {
        None if text == "auto" => Ok(ShardArg::Auto { count: None }),
        Some(("auto", n)) => Ok(ShardArg::Auto { count: Some(count(n)?) }),
        Some((i, n)) => {
            let count = count(n)?;
            let index = i.parse::<u32>().map_err(|_| format!("`{i}` is not a shard index (I in I/N counts from 0)"))?;
            checked(index, count, "").map(ShardArg::Given)
        }
        None => Err(format!("expected I/N (e.g. 0/4), auto or auto/N, got `{text}`")),
    }
}

/// The shard `index` of `count`, if the index is below the count; `source` says where the
/// index came from, for the message.
fn checked(index: u32, count: u32, source: &str) -> Result<Shard, String> {
    if index < count {
        Ok(Shard { index, count })
    } else {
        Err(format!("shard index {index}{source} is out of range for {count} shards (0 to {})", count - 1))
    }
}

/// The shard a run takes: `arg` if given, else the scheduler's if the environment `env` is a
/// job array's task; `None` for the whole sweep. The second value says where it came from.
///
/// # Errors
/// `--shard auto` outside a job array (a Slurm job that is not an array says so), an array
/// whose variables do not make an index within the count, a Kubernetes index without a count.
pub fn resolve(arg: Option<ShardArg>, env: &dyn Fn(&str) -> Option<String>) -> Result<Option<(Shard, String)>, String> {
    let count = match arg {
        Some(ShardArg::Given(shard)) => return Ok(Some((shard, "--shard".into()))),
        Some(ShardArg::Auto { count }) => count,
        None if env("SLURM_ARRAY_TASK_ID").is_some() || env("JOB_COMPLETION_INDEX").is_some() => None,
        None => return Ok(None),
    };
    let number = |name: &str| -> Result<Option<u32>, String> {
        env(name)
            .map(|value| value.trim().parse::<u32>().map_err(|_| format!("{name}={value} is not a whole number")))
            .transpose()
    };
    if let Some(id) = number("SLURM_ARRAY_TASK_ID")? {
        let total = number("SLURM_ARRAY_TASK_COUNT")?.ok_or_else(|| {
            format!("SLURM_ARRAY_TASK_ID={id} but no SLURM_ARRAY_TASK_COUNT: not a Slurm job array's task")
        })?;
        if let Some(given) = count.filter(|&n| n != total) {
            return Err(format!("--shard auto/{given} but the Slurm array has {total} tasks"));
        }
        let first = number("SLURM_ARRAY_TASK_MIN")?.unwrap_or(0);
        let step = number("SLURM_ARRAY_TASK_STEP")?.unwrap_or(1).max(1);
        let offset = id.checked_sub(first).filter(|o| o % step == 0).ok_or_else(|| {
            format!("SLURM_ARRAY_TASK_ID={id} is not on the array's range (from {first} in steps of {step})")
        })?;
        let source = format!(" (SLURM_ARRAY_TASK_ID={id})");
        return Ok(Some((checked(offset / step, total, &source)?, format!("Slurm array task {id}"))));
    }
    if let Some(index) = number("JOB_COMPLETION_INDEX")? {
        let Some(total) = count else {
            return Err(format!(
                "JOB_COMPLETION_INDEX={index} gives the shard's index, not the count: pass --shard auto/N with N the indexed job's completions"
            ));
        };
        let source = format!(" (JOB_COMPLETION_INDEX={index})");
        return Ok(Some((checked(index, total, &source)?, format!("Kubernetes completion index {index}"))));
    }
    match env("SLURM_JOB_ID") {
        Some(job) => Err(format!("--shard auto: Slurm job {job} is not a job array (no SLURM_ARRAY_TASK_ID): submit it with sbatch --array=0-N, or give --shard I/N")),
        None => Err("--shard auto: neither SLURM_ARRAY_TASK_ID (a Slurm job array) nor JOB_COMPLETION_INDEX (a Kubernetes indexed job) is set: give --shard I/N".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let vars: Vec<(String, String)> = vars.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
        move |name| vars.iter().find(|(k, _)| k == name).map(|(_, v)| v.clone())
    }

    fn shard(index: u32, count: u32) -> Shard {
        Shard { index, count }
    }

    #[test]
    fn shards_split_the_cases_disjointly() {
        let shards: Vec<Shard> = (0..4).map(|i| shard(i, 4)).collect();
        for case in 0..1000 {
            assert_eq!(shards.iter().filter(|s| s.contains(case)).count(), 1);
        }
        assert_eq!(shard(2, 4).file_name(), "shard-2-of-4.csv");
    }

    #[test]
    fn reads_the_flag_and_the_schedulers() {
        assert_eq!(parse("1/4"), Ok(ShardArg::Given(shard(1, 4))));
        assert_eq!(parse("auto"), Ok(ShardArg::Auto { count: None }));
        assert_eq!(parse("auto/8"), Ok(ShardArg::Auto { count: Some(8) }));
        assert_eq!(parse("4/4").unwrap_err(), "shard index 4 is out of range for 4 shards (0 to 3)");
        assert_eq!(parse("0/0").unwrap_err(), "the number of shards must be at least 1");
        assert_eq!(parse("2").unwrap_err(), "expected I/N (e.g. 0/4), auto or auto/N, got `2`");
        let none = env(&[]);
        assert_eq!(resolve(None, &none), Ok(None));
        let slurm = env(&[
            ("SLURM_JOB_ID", "12"),
            ("SLURM_ARRAY_TASK_ID", "3"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
            ("SLURM_ARRAY_TASK_MIN", "0"),
        ]);
        assert_eq!(resolve(None, &slurm), Ok(Some((shard(3, 4), "Slurm array task 3".into()))));
        // --array=1-7:2 gives ids 1, 3, 5, 7: shard (7 − 1)/2 = 3 of 4.
        let stepped = env(&[
            ("SLURM_ARRAY_TASK_ID", "7"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
            ("SLURM_ARRAY_TASK_MIN", "1"),
            ("SLURM_ARRAY_TASK_STEP", "2"),
        ]);
        assert_eq!(
            resolve(Some(ShardArg::Auto { count: None }), &stepped),
            Ok(Some((shard(3, 4), "Slurm array task 7".into())))
        );
        let given = resolve(Some(ShardArg::Given(shard(0, 2))), &slurm);
        assert_eq!(given, Ok(Some((shard(0, 2), "--shard".into()))), "the flag wins");
        let kubernetes = env(&[("JOB_COMPLETION_INDEX", "5")]);
        assert_eq!(
            resolve(Some(ShardArg::Auto { count: Some(8) }), &kubernetes),
            Ok(Some((shard(5, 8), "Kubernetes completion index 5".into())))
        );
    }

    #[test]
    fn says_what_is_wrong_with_the_environment() {
        let error = |arg: Option<ShardArg>, vars: &[(&str, &str)]| resolve(arg, &env(vars)).unwrap_err();
        let auto = Some(ShardArg::Auto { count: None });
        assert_eq!(
            error(auto, &[("SLURM_JOB_ID", "12")]),
            "--shard auto: Slurm job 12 is not a job array (no SLURM_ARRAY_TASK_ID): submit it with sbatch --array=0-N, or give --shard I/N"
        );
        assert!(error(auto, &[]).starts_with("--shard auto: neither SLURM_ARRAY_TASK_ID"));
        assert_eq!(
            error(None, &[("SLURM_ARRAY_TASK_ID", "2")]),
            "SLURM_ARRAY_TASK_ID=2 but no SLURM_ARRAY_TASK_COUNT: not a Slurm job array's task"
        );
        assert_eq!(
            error(None, &[("SLURM_ARRAY_TASK_ID", "4"), ("SLURM_ARRAY_TASK_COUNT", "4")]),
            "shard index 4 (SLURM_ARRAY_TASK_ID=4) is out of range for 4 shards (0 to 3)"
        );
        assert_eq!(
            error(None, &[("JOB_COMPLETION_INDEX", "1")]),
            "JOB_COMPLETION_INDEX=1 gives the shard's index, not the count: pass --shard auto/N with N the indexed job's completions"
        );
        assert_eq!(
            error(None, &[("SLURM_ARRAY_TASK_ID", "x"), ("SLURM_ARRAY_TASK_COUNT", "4")]),
            "SLURM_ARRAY_TASK_ID=x is not a whole number"
        );
    }
}
