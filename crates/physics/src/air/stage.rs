//! The air stage of a force evaluation (PHYSICS.md §10; after the couplings, before the water,
//! whose added mass reacts to every other force): each wind-loaded body's windage and rotor
//! thrust at the relative wind, recorded in its [`AirForces`] and added to its load; returns
//! their power, external work (booked as the water's is, §5).
//!
//! The mean speed and the gusts' amplitudes are those at each load point's height at t = 0 (a
//! floating body heaves and pitches little against the profile's scale); the velocity the
//! wind is relative to is the point's own, now.

use super::gusts::GustPoint;
use super::gusts::GustSpec;
use super::rotor::{Rotor, RotorSpec};
use super::wind::{Air, AirError, AirSpec, WindSpec};
use super::windage::{ExposedHull, Windage, WindageSpec, exposed_hull};
use crate::body::{BodyFrame, Load, RigidBody};
use crate::math::Vec3;
use crate::mesh::MeshError;
use crate::parameter::{Bound, ParameterError, require_derived};

/// What a scene says of the wind loads on one body: its windage, its rotor, either or both.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WindLoadSpec {
    pub windage: Option<WindageSpec>,
    pub rotor: Option<RotorSpec>,
}

/// A body's wind loads that cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WindLoadError {
    #[error("windage: {0}")]
    Windage(ParameterError),
    #[error("windage: its areas come from the hull above the water, and {0}: state them (areas: (Ax, Ay, Az))")]
    NoHull(MeshError),
    #[error("rotor: {0}")]
    Rotor(ParameterError),
}

/// Air that cannot load the system's bodies.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AirStageError {
    #[error(transparent)]
    Air(#[from] AirError),
    #[error("{source}")]
    Body { index: usize, source: WindLoadError },
}

/// One load point: the mean wind speed at its height [m/s] and its gusts.
#[derive(Debug, Clone, PartialEq)]
struct Exposure {
    mean: f64,
    gusts: GustPoint,
}

/// A wind-loaded body: its index, windage and rotor, each with its exposure.
#[derive(Debug, Clone, PartialEq)]
pub struct WindBody {
    body: usize,
    windage: Option<(Windage, Exposure)>,
    rotor: Option<(Rotor, Exposure)>,
}

impl WindBody {
    /// The body's index in the system.
    pub fn body(&self) -> usize {
        self.body
    }

    /// Its windage, if it has one.
    pub fn windage(&self) -> Option<&Windage> {
        self.windage.as_ref().map(|(w, _)| w)
    }

    /// Its rotor, if it has one.
    pub fn rotor(&self) -> Option<&Rotor> {
        self.rotor.as_ref().map(|(r, _)| r)
    }

    /// The mean wind speed at its windage's centre and at its rotor's hub at t = 0 [m/s].
    pub fn mean_speeds(&self) -> (Option<f64>, Option<f64>) {
        (self.windage.as_ref().map(|(_, e)| e.mean), self.rotor.as_ref().map(|(_, e)| e.mean))
    }

    /// The wind speeds \[m/s] the stable step linearises the damping at, at the windage's centre
    /// and the rotor's hub: the mean plus four of the gusts' standard deviations.
    pub fn speeds_for_damping(&self) -> (Option<f64>, Option<f64>) {
        let speed = |e: &Exposure| e.mean + 4.0 * e.gusts.variance().sqrt();
        (self.windage.as_ref().map(|(_, e)| speed(e)), self.rotor.as_ref().map(|(_, e)| speed(e)))
    }
}

/// What the air did to one body at an evaluation, about G, world axes [N, N·m].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AirForces {
    /// Index of the body.
    pub body: usize,
    /// The wind's drag on the body's windage.
    pub windage: Load,
    /// The rotor's thrust.
    pub rotor: Load,
    /// `F·v + M·ω` of both \[W].
    pub power: f64,
}

impl AirForces {
    /// Everything the air does to the body.
    pub fn total(&self) -> Load {
        Load { force: self.windage.force + self.rotor.force, moment: self.windage.moment + self.rotor.moment }
    }
}

/// The air and the bodies it loads.
#[derive(Debug, Clone, PartialEq)]
pub struct AirStage {
    air: Air,
    bodies: Vec<WindBody>,
}

/// The stage's inputs at one evaluation.
pub struct AirStageInputs<'a> {
    pub bodies: &'a [RigidBody],
    pub frames: &'a [BodyFrame],
    pub loads: &'a mut [Load],
    /// One record per wind-loaded body.
    pub records: &'a mut [AirForces],
}

impl AirStage {
    /// The air of `spec` loading each `(body, spec)` of `loads`, the bodies at `frames` at t = 0
    /// and heights measured from `level` \[m] (the still water level, or 0).
    ///
    /// # Errors
    /// The air's own error, or the index of the body whose loads cannot be built and why.
    pub fn new(
        spec: AirSpec,
        loads: Vec<(usize, WindLoadSpec)>,
        bodies: &[RigidBody],
        frames: &[BodyFrame],
        level: f64,
    ) -> Result<Self, AirStageError> {
        let air = Air::new(spec)?;
        let bodies = loads
            .into_iter()
            .map(|(index, spec)| {
                wind_body(&air, index, &spec, &bodies[index], &frames[index], level)
                    .map_err(|source| AirStageError::Body { index, source })
            })
            .collect::<Result<_, _>>()?;
        Ok(Self { air, bodies })
    }

    /// The air.
    pub fn air(&self) -> &Air {
        &self.air
    }

    /// The wind-loaded bodies.
    pub fn bodies(&self) -> &[WindBody] {
        &self.bodies
    }

    /// The stage as a static solve sees it (`crate::system::System::at_rest`): the mean wind
    /// at full strength from t = 0, no gusts.
    pub fn at_rest(&self) -> Self {
        let spec = AirSpec {
            ramp: 0.0,
            wind: WindSpec { gusts: GustSpec::Steady, ..self.air.spec().wind },
            ..*self.air.spec()
        };
        // A steady wind without a ramp passes every check the accepted air passed.
        let air = Air::new(spec).expect("steady air from accepted air");
        let steady = |exposure: &Exposure| Exposure { mean: exposure.mean, gusts: GustPoint::default() };
        let bodies = self
            .bodies
            .iter()
            .map(|b| WindBody {
                body: b.body,
                windage: b.windage.as_ref().map(|(w, e)| (*w, steady(e))),
                rotor: b.rotor.as_ref().map(|(r, e)| (r.clone(), steady(e))),
            })
            .collect();
        Self { air, bodies }
    }

    /// Stage *air* at `time` \[s]: each wind-loaded body's forces into `on.records` and added to
    /// `on.loads`; returns their power \[W]. A prescribed motion feels nothing.
    pub fn apply(&self, on: AirStageInputs<'_>, time: f64) -> f64 {
        let AirStageInputs { bodies, frames, loads, records } = on;
        let ramp = self.air.ramp(time);
        let mut power = 0.0;
        for (loaded, record) in self.bodies.iter().zip(records.iter_mut()) {
            *record = AirForces { body: loaded.body, ..AirForces::default() };
            if bodies[loaded.body].is_kinematic() || ramp == 0.0 {
                continue;
            }
            *record = self.body_forces(loaded, &frames[loaded.body], ramp, time);
            let total = record.total();
            loads[loaded.body].force += total.force;
            loads[loaded.body].moment += total.moment;
            power += record.power;
        }
        power
    }

    /// The air's forces on one body at `frame`, the wind ramped by `ramp`.
    fn body_forces(&self, loaded: &WindBody, frame: &BodyFrame, ramp: f64, time: f64) -> AirForces {
        let omega = frame.rotation * frame.angular_velocity;
        let density = self.air.density();
        let (windage_gust, rotor_gust) = self.gust_speeds(loaded, time);
        // The wind at a point of mean speed `mean` and gust `gust`, relative to a point `arm` from G.
        let relative = |mean: f64, gust: f64, arm: &Vec3| {
            let wind = self.air.direction() * ((mean + gust) * ramp);
            wind - (frame.velocity + omega.cross(arm))
        };
        let mut record = AirForces { body: loaded.body, ..AirForces::default() };
        if let Some((windage, exposure)) = &loaded.windage {
            let arm = frame.rotation * windage.center();
            let force = windage.force(&frame.rotation, &relative(exposure.mean, windage_gust, &arm), density);
            record.windage = Load { force, moment: arm.cross(&force) };
        }
        if let Some((rotor, exposure)) = &loaded.rotor {
            let arm = frame.rotation * rotor.hub();
            let axis = frame.rotation * rotor.axis();
            let force = rotor.force(&axis, &relative(exposure.mean, rotor_gust, &arm), density);
            record.rotor = Load { force, moment: arm.cross(&force) };
        }
        record.power = crate::water_stage::power(&record.total(), frame);
        record
    }
}

impl AirStage {
    /// The gusts [m/s] at a body's windage and rotor at `time` \[s] (0 where it has none), each
    /// component's cosine once for both.
    fn gust_speeds(&self, loaded: &WindBody, time: f64) -> (f64, f64) {
        let gusts = self.air.gusts();
        if gusts.is_steady() {
            return (0.0, 0.0);
        }
        match (&loaded.windage, &loaded.rotor) {
            (Some((_, w)), Some((_, r))) => {
                let [windage, rotor] = gusts.speeds(&[&w.gusts, &r.gusts], time);
                (windage, rotor)
            }
            (Some((_, w)), None) => (gusts.speed(&w.gusts, time), 0.0),
            (None, Some((_, r))) => (0.0, gusts.speed(&r.gusts, time)),
            (None, None) => (0.0, 0.0),
        }
    }
}

/// Body `index`'s wind loads in `air`, from its pose `frame` at t = 0 (module docs).
fn wind_body(
    air: &Air,
    index: usize,
    spec: &WindLoadSpec,
    body: &RigidBody,
    frame: &BodyFrame,
    level: f64,
) -> Result<WindBody, WindLoadError> {
    let axes = body.reference_in_principal.rotation.to_rotation_matrix().into_inner();
    let origin = body.reference_in_principal.translation.vector;
    let u10 = air.mean_speed(10.0);
    // The mean wind and the gusts' variance at a load point, derived from the checked wind:
    // refused when they overflow, naming the wind's speed.
    let exposure = |point: &Vec3| {
        let height = (frame.position + frame.rotation * point).z - level;
        let mean = air.mean_speed(height);
        let gusts = air.gusts().at(height, u10, mean);
        let speed = [("speed", air.spec().wind.speed)];
        require_derived("the mean wind at a load point", mean, Bound::NonNegative, "m/s", &speed)?;
        require_derived("the gusts' variance at a load point", gusts.variance(), Bound::NonNegative, "m²/s²", &speed)?;
        Ok(Exposure { mean, gusts })
    };
    let windage = match &spec.windage {
        None => None,
        Some(windage) => {
            let exposed = match windage.areas {
                Some(_) => ExposedHull { areas: [0.0; 3], centroid: Vec3::zeros() },
                None => {
                    let hull = crate::water::Hull::of_body(body).map_err(WindLoadError::NoHull)?;
                    exposed_hull(hull.vertices(), hull.triangles(), &frame.position, &frame.rotation, level)
                }
            };
            let windage = Windage::new(windage, axes, origin, &exposed).map_err(WindLoadError::Windage)?;
            let at = exposure(windage.center()).map_err(WindLoadError::Windage)?;
            Some((windage, at))
        }
    };
    let rotor = match &spec.rotor {
        None => None,
        Some(rotor) => {
            let rotor = Rotor::new(rotor, &axes, &origin).map_err(WindLoadError::Rotor)?;
            let at = exposure(rotor.hub()).map_err(WindLoadError::Rotor)?;
            Some((rotor, at))
        }
    };
    Ok(WindBody { body: index, windage, rotor })
}
