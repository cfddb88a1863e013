//! What a measured record's column can be in the Fit panel: each body's and coupling's model
//! signals ([`signals`]), and how the column choice names them ([`signal_label`]).

use tether_analysis::quantity::{Axis, End, EnergyPart, Quantity, Turn};
use tether_scene::SceneFile;
use tether_scene::file::CouplingDef;

/// The model signals a measured column can be: each body's position, velocity and roll, pitch,
/// yaw; each coupling's tension (a contact's normal force), a spring's or line's length, a line's
/// end tensions.
pub fn signals(file: &SceneFile) -> Vec<Quantity> {
    let mut signals = Vec::new();
    for body in &file.bodies {
        let name = || body.name.clone();
        signals.extend([Axis::X, Axis::Y, Axis::Z].map(|axis| Quantity::Position(name(), axis)));
        signals.extend([Axis::X, Axis::Y, Axis::Z].map(|axis| Quantity::Velocity(name(), axis)));
        signals.extend([Turn::Roll, Turn::Pitch, Turn::Yaw].map(|turn| Quantity::Angle(name(), turn)));
    }
    for def in &file.couplings {
        let name = || def.name().to_string();
        match def {
            CouplingDef::SpringDamper { .. } => signals.extend([Quantity::Tension(name()), Quantity::Length(name())]),
            CouplingDef::Catenary { .. } => signals.extend([
                Quantity::Tension(name()),
                Quantity::EndTension(name(), End::End1),
                Quantity::EndTension(name(), End::End2),
                Quantity::Length(name()),
            ]),
            CouplingDef::Contact { .. } => signals.push(Quantity::Tension(name())),
        }
    }
    signals
}

/// A signal as the column choice shows it: `m: position x [m]`, `chain: end 2 tension [N]` (the
/// unit the quantity's own).
pub fn signal_label(quantity: &Quantity) -> String {
    let axis = |axis: &Axis| match axis {
        Axis::X => "x",
        Axis::Y => "y",
        Axis::Z => "z",
    };
    let end = |end: &End| match end {
        End::End1 => "end 1",
        End::End2 => "end 2",
    };
    let what = match quantity {
        Quantity::Tension(c) => format!("{c}: tension"),
        Quantity::EndTension(c, e) => format!("{c}: {} tension", end(e)),
        Quantity::EndForce(c, e, a) => format!("{c}: {} force {}", end(e), axis(a)),
        Quantity::Length(c) => format!("{c}: length"),
        Quantity::Position(b, a) => format!("{b}: position {}", axis(a)),
        Quantity::Velocity(b, a) => format!("{b}: velocity {}", axis(a)),
        Quantity::Angle(b, turn) => {
            let turn = match turn {
                Turn::Roll => "roll",
                Turn::Pitch => "pitch",
                Turn::Yaw => "yaw",
            };
            format!("{b}: {turn}")
        }
        Quantity::AngularVelocity(b, a) => format!("{b}: angular velocity {}", axis(a)),
        Quantity::Speed(b) => format!("{b}: speed"),
        Quantity::AngularSpeed(b) => format!("{b}: angular speed"),
        Quantity::Excursion(b) => format!("{b}: excursion"),
        Quantity::Rotation(b) => format!("{b}: rotation"),
        Quantity::Energy(part) => {
            let part = match part {
                EnergyPart::Kinetic => "kinetic",
                EnergyPart::Gravity => "gravity",
                EnergyPart::Elastic => "elastic",
                EnergyPart::Dissipated => "dissipated",
                EnergyPart::ExternalWork => "external work",
                EnergyPart::Total => "total",
                EnergyPart::Balance => "balance",
            };
            format!("energy: {part}")
        }
    };
    format!("{what} [{}]", quantity.unit())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// A float held by a spring and a quasi-static line.
    const SCENE: &str = r#"Scene(dt: 0.01, bodies: [Body(name: "float",
            master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
            shape: Sphere(radius: 0.5))],
        couplings: [
            SpringDamper(name: "spring", end1: World((0.0, 0.0, 5.0)), end2: Body(body: "float"),
                law: Linear(stiffness: 100.0, rest_length: 4.0)),
            Catenary(name: "line", end1: World((20.0, 0.0, 0.0)), end2: Body(body: "float"),
                mass_per_length: 50.0, length: 25.0, stiffness: 1e8),
        ])"#;

    #[test]
    fn each_body_and_coupling_offers_its_signals() {
        let file = tether_scene::parse(SCENE, Path::new("float.ron")).unwrap().file;
        let labels: Vec<String> = signals(&file).iter().map(signal_label).collect();
        assert_eq!(labels.len(), 9 + 2 + 4);
        assert_eq!(labels[2], "float: position z [m]");
        assert!(labels.contains(&"line: end 2 tension [N]".to_string()), "{labels:?}");
    }
}
