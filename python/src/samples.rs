//! A run's samples, gathered as flat `f64` columns (one row per sample) and handed to Python as
//! bytes with their shapes; `tether/_arrays.py` views them as numpy arrays without a copy.

use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyDict};
use tether_analysis::statics::data::body_quaternion;
use tether_physics::world::World;

/// Columns per sample, with the trailing shape of one sample's values.
pub struct Samples {
    bodies: usize,
    couplings: usize,
    /// Simulated time \[s].
    time: Vec<f64>,
    /// Per body: centre of mass, world \[m]; orientation of the body's frame `[w, x, y, z]`;
    /// velocity of G \[m/s]; angular velocity, world \[rad/s].
    position: Vec<f64>,
    quaternion: Vec<f64>,
    velocity: Vec<f64>,
    angular_velocity: Vec<f64>,
    /// Per coupling: end points, world \[m]; the force it exerts on end 1 and on end 2 \[N];
    /// its scalar force (tension, positive pulling the ends together) \[N].
    point1: Vec<f64>,
    point2: Vec<f64>,
    force1: Vec<f64>,
    force2: Vec<f64>,
    tension: Vec<f64>,
    /// Energy terms (PHYSICS.md §5) \[J]: kinetic, gravity, elastic, dissipated, external
    /// work, and the balance `kinetic + gravity + elastic + dissipated − external work`.
    energy: [Vec<f64>; 6],
}

/// The energy columns' names, in order.
const ENERGY: [&str; 6] = ["kinetic", "gravity", "elastic", "dissipated", "external_work", "balance"];

impl Samples {
    /// Room for `capacity` samples of `world`.
    pub fn new(world: &World, capacity: usize) -> Self {
        let (bodies, couplings) = (world.bodies().len(), world.couplings().len());
        let with = |per: usize| Vec::with_capacity(capacity * per);
        Self {
            bodies,
            couplings,
            time: with(1),
            position: with(3 * bodies),
            quaternion: with(4 * bodies),
            velocity: with(3 * bodies),
            angular_velocity: with(3 * bodies),
            point1: with(3 * couplings),
            point2: with(3 * couplings),
            force1: with(3 * couplings),
            force2: with(3 * couplings),
            tension: with(couplings),
            energy: std::array::from_fn(|_| with(1)),
        }
    }

    /// Bytes one sample takes.
    pub fn bytes_per_sample(bodies: usize, couplings: usize) -> usize {
        8 * (1 + 13 * bodies + 13 * couplings + ENERGY.len())
    }

    /// Appends the world's current state.
    pub fn push(&mut self, world: &World) {
        self.time.push(world.time());
        for (index, body) in world.bodies().iter().enumerate() {
            let state = world.state(index);
            self.position.extend(state.position.iter());
            self.quaternion.extend(body_quaternion(body, &state));
            self.velocity.extend(state.velocity.iter());
            self.angular_velocity.extend(state.angular_velocity.iter());
        }
        for forces in world.coupling_forces() {
            self.point1.extend(forces.point1.iter());
            self.point2.extend(forces.point2.iter());
            self.force1.extend(forces.f1.iter());
            self.force2.extend(forces.f2.iter());
            self.tension.push(forces.tension);
        }
        let energy = world.energy();
        let terms =
            [energy.kinetic, energy.gravity, energy.elastic, energy.dissipated, energy.external_work, energy.balance()];
        for (column, value) in self.energy.iter_mut().zip(terms) {
            column.push(value);
        }
    }

    /// `{name: (bytes, shape)}`, the energy terms under `energy_<term>`.
    pub fn into_dict<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let n = self.time.len();
        let (b, c) = (self.bodies, self.couplings);
        let dict = PyDict::new(py);
        let put = |name: &str, values: &[f64], shape: Vec<usize>| dict.set_item(name, (bytes(py, values), shape));
        put("time", &self.time, vec![n])?;
        put("position", &self.position, vec![n, b, 3])?;
        put("quaternion", &self.quaternion, vec![n, b, 4])?;
        put("velocity", &self.velocity, vec![n, b, 3])?;
        put("angular_velocity", &self.angular_velocity, vec![n, b, 3])?;
        put("point1", &self.point1, vec![n, c, 3])?;
        put("point2", &self.point2, vec![n, c, 3])?;
        put("force1", &self.force1, vec![n, c, 3])?;
        put("force2", &self.force2, vec![n, c, 3])?;
        put("tension", &self.tension, vec![n, c])?;
        for (name, column) in ENERGY.iter().zip(&self.energy) {
            put(&format!("energy_{name}"), column, vec![n])?;
        }
        Ok(dict)
    }
}

/// `values` as native-endian bytes (numpy's `float64`), in a `bytearray` so the arrays are writable.
pub fn bytes<'py>(py: Python<'py>, values: &[f64]) -> Bound<'py, PyByteArray> {
    let raw: Vec<u8> = values.iter().flat_map(|x| x.to_ne_bytes()).collect();
    PyByteArray::new(py, &raw)
}
