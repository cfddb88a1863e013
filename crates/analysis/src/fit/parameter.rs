//! A fitted parameter: the scene values it sets (the sweep's value paths), its bounds and scale,
//! and its map to the solver's unit interval (docs/calibration.md, "The spec").
//!
//! `Linear`: `θ = from + z (to − from)`, `dθ/dz = to − from`; `Log`: `θ = from (to/from)^z`,
//! `dθ/dz = θ ln(to/from)`. The bounds are checked here (finite, `from < to`, both > 0 on a log
//! scale); whether the scene takes a value is the scene loader's to say, when the fit builds the
//! scene with each bound ([`super::setup`]).

use super::spec::{ParameterDef, Scale, ShiftDef};
use super::uncertainty::Scaling;
use crate::value_path::ValuePath;
use serde_json::Value;

/// What a parameter sets.
#[derive(Debug, Clone, PartialEq)]
pub enum Target {
    /// Values of the scene file.
    Scene(Vec<ValuePath>),
    /// The time shift `τ` \[s] between the model and the record.
    TimeShift,
}

/// A parameter, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    pub name: String,
    pub target: Target,
    pub from: f64,
    pub to: f64,
    pub scale: Scale,
    /// The start value.
    pub start: f64,
    /// The value in the scene file (`None`: the scene leaves it to its default; the time shift).
    pub scene_value: Option<f64>,
}

impl Parameter {
    /// The parameter `def` of the scene whose data is `tree`.
    ///
    /// # Errors
    /// A path that leads nowhere, bounds that are not finite, inverted, or not positive on a log
    /// scale, a start outside the bounds, several paths without a name.
    pub fn new(def: &ParameterDef, tree: &Value) -> Result<Self, String> {
        let texts = def.path.paths();
        let name = match (&def.name, texts) {
            (Some(name), _) => name.clone(),
            (None, [one]) => one.clone(),
            (None, _) => return Err("a parameter that sets several paths needs a `name`".into()),
        };
        let paths = texts
            .iter()
            .map(|text| ValuePath::find(tree, text).map_err(|m| format!("parameter `{name}`: {m}")))
            .collect::<Result<Vec<_>, _>>()?;
        if paths.is_empty() {
            return Err(format!("parameter `{name}` sets no path"));
        }
        check_bounds(&name, def.from, def.to, def.scale)?;
        let scene_value = paths[0].get(tree).and_then(Value::as_f64);
        let start = start_value(&name, def.start, scene_value, def.from, def.to, def.scale)?;
        Ok(Self {
            name,
            target: Target::Scene(paths),
            from: def.from,
            to: def.to,
            scale: def.scale,
            start,
            scene_value,
        })
    }

    /// The time shift `def`.
    ///
    /// # Errors
    /// Bounds that are not finite or inverted, a start outside them.
    pub fn time_shift(def: &ShiftDef) -> Result<Self, String> {
        let name = "time_shift".to_string();
        check_bounds(&name, def.from, def.to, Scale::Linear)?;
        let start = start_value(&name, def.start, Some(0.0), def.from, def.to, Scale::Linear)?;
        Ok(Self {
            name,
            target: Target::TimeShift,
            from: def.from,
            to: def.to,
            scale: Scale::Linear,
            start,
            scene_value: None,
        })
    }

    /// `θ(z)`.
    pub fn value(&self, z: f64) -> f64 {
        match self.scale {
            Scale::Linear => self.from + z * (self.to - self.from),
            Scale::Log => self.from * (self.to / self.from).powf(z),
        }
    }

    /// `z(θ)`.
    pub fn unit(&self, value: f64) -> f64 {
        match self.scale {
            Scale::Linear => (value - self.from) / (self.to - self.from),
            Scale::Log => (value / self.from).ln() / (self.to / self.from).ln(),
        }
    }

    /// `θ` and `dθ/dz` at `z`.
    pub fn scaling(&self, z: f64) -> Scaling {
        let value = self.value(z);
        let derivative = match self.scale {
            Scale::Linear => self.to - self.from,
            Scale::Log => value * (self.to / self.from).ln(),
        };
        let span = self.to - self.from;
        let reference = if value.abs() > 1e-6 * span { value.abs() } else { span };
        Scaling { value, derivative, reference }
    }

    /// Writes `value` at every path of the parameter into `tree` (the time shift sets none).
    pub fn set(&self, tree: &mut Value, value: f64) {
        if let Target::Scene(paths) = &self.target {
            for path in paths {
                path.set(tree, Value::from(value));
            }
        }
    }
}

fn check_bounds(name: &str, from: f64, to: f64, scale: Scale) -> Result<(), String> {
    if !(from.is_finite() && to.is_finite()) {
        return Err(format!("parameter `{name}`: bounds must be finite, got from {from} to {to}"));
    }
    if !(from < to) {
        return Err(format!("parameter `{name}`: `from` ({from}) must be below `to` ({to})"));
    }
    if scale == Scale::Log && !(from > 0.0) {
        return Err(format!("parameter `{name}`: a Log scale needs bounds > 0, got from {from}"));
    }
    Ok(())
}

fn start_value(
    name: &str,
    given: Option<f64>,
    scene: Option<f64>,
    from: f64,
    to: f64,
    scale: Scale,
) -> Result<f64, String> {
    let middle = match scale {
        Scale::Linear => 0.5 * (from + to),
        Scale::Log => (from * to).sqrt(),
    };
    match given {
        Some(start) if !(start >= from && start <= to) => {
            Err(format!("parameter `{name}`: start {start} is outside its bounds [{from}, {to}]"))
        }
        Some(start) => Ok(start),
        None => Ok(scene.filter(|v| *v >= from && *v <= to).unwrap_or(middle)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec_text::PathsDef;

    fn def(from: f64, to: f64, scale: Scale) -> ParameterDef {
        ParameterDef { name: None, path: PathsDef::One("dt".into()), from, to, scale, start: None }
    }

    #[test]
    fn maps_to_the_unit_interval_and_back() {
        let tree = serde_json::json!({"dt": 0.01});
        for scale in [Scale::Linear, Scale::Log] {
            let p = Parameter::new(&def(1e-3, 1e-1, scale), &tree).unwrap();
            assert_eq!(p.start, 0.01, "the scene's value inside the bounds");
            for z in [0.0, 0.3, 1.0] {
                assert!((p.unit(p.value(z)) - z).abs() < 1e-12);
                // dθ/dz against a central difference.
                let h = 1e-6;
                let numeric = (p.value(z + h) - p.value(z - h)) / (2.0 * h);
                assert!((p.scaling(z).derivative - numeric).abs() < 1e-6 * numeric.abs());
            }
        }
    }

    #[test]
    fn refuses_bad_bounds() {
        let tree = serde_json::json!({"dt": 0.01});
        assert!(Parameter::new(&def(1.0, 0.5, Scale::Linear), &tree).unwrap_err().contains("must be below"));
        assert!(Parameter::new(&def(-1.0, 1.0, Scale::Log), &tree).unwrap_err().contains("bounds > 0"));
        assert!(Parameter::new(&def(f64::NAN, 1.0, Scale::Linear), &tree).unwrap_err().contains("finite"));
        let mut outside = def(1.0, 2.0, Scale::Linear);
        outside.start = Some(3.0);
        assert!(Parameter::new(&outside, &tree).unwrap_err().contains("outside its bounds"));
        // The scene's value outside the bounds: the fit starts in the middle.
        assert_eq!(Parameter::new(&def(1.0, 2.0, Scale::Linear), &tree).unwrap().start, 1.5);
        let mut nowhere = def(1.0, 2.0, Scale::Linear);
        nowhere.path = PathsDef::One("bodies.nobody.mass".into());
        assert!(Parameter::new(&nowhere, &tree).is_err());
    }
}
