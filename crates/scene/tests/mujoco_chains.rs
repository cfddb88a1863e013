//! The MJCF twins of the bench chains (`scenes/bench/chain100*.xml`, timed against Tether by
//! `scripts/mujoco-compare.sh`) hold the same chain as the RON files: the step, gravity, each
//! ball's mass, inertia, radius and starting place, each spring's ends, stiffness, damping and
//! rest length, the ground's friction where there is contact. An edit of one file without the
//! other fails here, with no MuJoCo needed.

use tether_test_support as common;

use roxmltree::{Document, Node};
use tether_physics::body::Shape;
use tether_physics::coupling::{CouplingKind, ElasticLaw, Endpoint};
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// The numbers of an attribute: `"0.1 0 3"` → `[0.1, 0.0, 3.0]`.
fn numbers(node: Node, attribute: &str) -> Vec<f64> {
    let text = node.attribute(attribute).unwrap_or_else(|| panic!("<{}> has {attribute}", node.tag_name().name()));
    text.split_whitespace().map(|word| word.parse().unwrap_or_else(|e| panic!("{attribute}={text}: {e}"))).collect()
}

fn element<'a>(parent: Node<'a, 'a>, tag: &str) -> Node<'a, 'a> {
    parent.children().find(|n| n.has_tag_name(tag)).unwrap_or_else(|| panic!("<{tag}> in the MJCF"))
}

fn vector(values: &[f64]) -> Vec3 {
    Vec3::from_column_slice(values)
}

/// Where a tendon's site is, as a Tether end: a point of a ball or of the world.
fn site_end(document: &Document, world: &World, name: &str) -> Endpoint {
    let site = document
        .descendants()
        .find(|n| n.has_tag_name("site") && n.attribute("name") == Some(name))
        .unwrap_or_else(|| panic!("site {name}"));
    let parent = site.parent_element().expect("a site has a parent element");
    if parent.has_tag_name("worldbody") {
        Endpoint::World(vector(&numbers(site, "pos")))
    } else {
        let ball = parent.attribute("name").expect("a ball has a name");
        let body =
            world.bodies().iter().position(|b| b.name == ball).unwrap_or_else(|| panic!("{ball} in the RON file"));
        // MJCF's default place of a site is its body's origin, here the centre of mass.
        let point = site.attribute("pos").map_or_else(Vec3::zeros, |_| vector(&numbers(site, "pos")));
        Endpoint::Body { body, point }
    }
}

/// An end as (the body it is on, the point): `None` and the world point for an anchor, the body
/// and the point in its principal frame otherwise (its centre for `Center`).
fn placed(end: &Endpoint) -> (Option<usize>, Vec3) {
    match end {
        Endpoint::World(point) => (None, *point),
        Endpoint::Body { body, point } => (Some(*body), *point),
        Endpoint::Center { body } => (Some(*body), Vec3::zeros()),
    }
}

fn assert_same_chain(stem: &str) {
    let world = tether_scene::load(&common::repo(&format!("scenes/bench/{stem}.ron"))).unwrap().world;
    let text = std::fs::read_to_string(common::repo(&format!("scenes/bench/{stem}.xml"))).unwrap();
    let document = Document::parse(&text).unwrap_or_else(|e| panic!("{stem}.xml: {e}"));
    let root = document.root_element();
    let option = element(root, "option");
    assert_eq!(numbers(option, "timestep"), [world.dt()], "{stem}");
    assert_eq!(vector(&numbers(option, "gravity")), *world.gravity(), "{stem}");
    assert_eq!(option.attribute("integrator"), Some("Euler"), "{stem}: the leapfrog's twin");

    let worldbody = element(root, "worldbody");
    let balls: Vec<Node> = worldbody.children().filter(|n| n.has_tag_name("body")).collect();
    assert_eq!(balls.len(), world.bodies().len(), "{stem}");
    for (index, (ball, body)) in balls.iter().zip(world.bodies()).enumerate() {
        assert_eq!(ball.attribute("name"), Some(body.name.as_str()), "{stem}");
        assert_eq!(vector(&numbers(*ball, "pos")), world.state(index).position, "{stem} {}", body.name);
        let inertial = element(*ball, "inertial");
        assert_eq!(numbers(inertial, "mass"), [body.mass()], "{stem} {}", body.name);
        assert_eq!(vector(&numbers(inertial, "diaginertia")), body.principal_moments(), "{stem} {}", body.name);
        let Shape::Sphere { radius, .. } = body.shape else { panic!("{stem} {}: a sphere", body.name) };
        assert_eq!(numbers(element(*ball, "geom"), "size"), [radius], "{stem} {}", body.name);
        assert!(ball.children().any(|n| n.has_tag_name("freejoint")), "{stem} {}: six dof", body.name);
    }

    let tendons: Vec<Node> = element(root, "tendon").children().filter(|n| n.has_tag_name("spatial")).collect();
    let springs: Vec<_> = world
        .couplings()
        .iter()
        .filter_map(|c| match &c.kind {
            CouplingKind::SpringDamper(spring) => Some((c.name.as_str(), spring)),
            CouplingKind::Catenary(_) | CouplingKind::Contact(_) => None,
        })
        .collect();
    assert_eq!(tendons.len(), springs.len(), "{stem}");
    for (tendon, (name, spring)) in tendons.iter().zip(&springs) {
        assert_eq!(tendon.attribute("name"), Some(*name), "{stem}");
        let ElasticLaw::Linear { stiffness, rest_length } = spring.law() else { panic!("{stem} {name}: linear") };
        assert_eq!(numbers(*tendon, "stiffness"), [*stiffness], "{stem} {name}");
        assert_eq!(numbers(*tendon, "damping"), [spring.damping()], "{stem} {name}");
        assert_eq!(numbers(*tendon, "springlength"), [*rest_length], "{stem} {name}");
        let sites: Vec<Endpoint> = tendon
            .children()
            .filter(|n| n.has_tag_name("site"))
            .map(|n| site_end(&document, &world, n.attribute("site").expect("a tendon's site is named")))
            .collect();
        assert_eq!(sites.len(), 2, "{stem} {name}");
        assert_eq!(
            [placed(&spring.end1()), placed(&spring.end2())],
            [placed(&sites[0]), placed(&sites[1])],
            "{stem} {name}"
        );
    }

    let contacts: Vec<f64> = world
        .couplings()
        .iter()
        .filter_map(|c| match &c.kind {
            CouplingKind::Contact(contact) => Some(contact.law().friction()),
            CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => None,
        })
        .collect();
    let ground = worldbody.children().find(|n| n.has_tag_name("geom") && n.attribute("type") == Some("plane"));
    match ground {
        Some(plane) => {
            assert_eq!(contacts.len(), balls.len(), "{stem}: every ball against the ground");
            assert!(contacts.iter().all(|&mu| numbers(plane, "friction")[0] == mu), "{stem}: {contacts:?}");
        }
        None => {
            assert!(contacts.is_empty(), "{stem}: no contact in the RON file either");
            assert_eq!(element(option, "flag").attribute("contact"), Some("disable"), "{stem}");
        }
    }
}

#[test]
fn the_mjcf_chain_in_air_is_the_ron_chain() {
    assert_same_chain("chain100_air");
}

#[test]
fn the_mjcf_chain_on_the_ground_is_the_ron_chain() {
    assert_same_chain("chain100");
}
