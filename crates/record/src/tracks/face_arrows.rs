//! Face arrows: `world/contacts/<name>` holds a contact's face forces as arrows from the face
//! centroids — those above a thousandth of the body's weight (`m·max(|g|, 1 m/s²)`), the
//! largest of the frame one body radius long (the force itself is in `plots/contact`) — for the
//! contacts and the frames the user asked for ([`FaceArrows`]); none by default. They take the
//! faces evaluated again, which the step does not keep, and they are the costliest entity of a
//! recording: a contact's arrows are drawn only where asked for.

use super::{Settings, Track, f32x3, send_chunk};
use crate::columns::{column, floats};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::{Contact, CouplingKind};
use tether_physics::world::World;

/// Face forces below this fraction of the body's weight are not drawn.
const ARROW_THRESHOLD: f64 = 1e-3;

/// Colour of the arrows: red, green, blue.
const ARROW_RGB: [u8; 3] = [230, 120, 40];

/// Which contacts have their face forces drawn as arrows, and when.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FaceArrows {
    pub contacts: ArrowedContacts,
    /// Drawn from this simulated time on \[s] (`None`: from the start).
    pub from: Option<f64>,
    /// Drawn up to this simulated time \[s] (`None`: to the end).
    pub until: Option<f64>,
}

/// The contacts whose face forces are drawn.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum ArrowedContacts {
    #[default]
    None,
    All,
    /// These contacts, by name.
    Named(Vec<String>),
}

impl FaceArrows {
    /// Every contact's, all the time.
    pub fn all() -> Self {
        Self { contacts: ArrowedContacts::All, ..Self::default() }
    }

    /// Whether every contact named is one of `world`'s.
    ///
    /// # Errors
    /// The first name that is not, with the names that are.
    pub fn check(&self, world: &World) -> Result<(), RecordError> {
        self.resolve(world).map(|_| ())
    }

    /// Which of `world`'s couplings are drawn, and when.
    ///
    /// # Errors
    /// A name that is not one of the world's contacts.
    pub(crate) fn resolve(&self, world: &World) -> Result<DrawnFaces, RecordError> {
        let is_contact = |kind: &CouplingKind| matches!(kind, CouplingKind::Contact(_));
        let couplings = world.couplings();
        let contacts = match &self.contacts {
            ArrowedContacts::None => vec![false; couplings.len()],
            ArrowedContacts::All => couplings.iter().map(|c| is_contact(&c.kind)).collect(),
            ArrowedContacts::Named(names) => {
                if let Some(unknown) =
                    names.iter().find(|name| !couplings.iter().any(|c| &c.name == *name && is_contact(&c.kind)))
                {
                    let known: Vec<&str> =
                        couplings.iter().filter(|c| is_contact(&c.kind)).map(|c| c.name.as_str()).collect();
                    return Err(RecordError::UnknownContact {
                        name: unknown.clone(),
                        known: if known.is_empty() { "none".into() } else { known.join(", ") },
                    });
                }
                couplings.iter().map(|c| names.contains(&c.name) && is_contact(&c.kind)).collect()
            }
        };
        Ok(DrawnFaces {
            contacts,
            from: self.from.unwrap_or(f64::NEG_INFINITY),
            until: self.until.unwrap_or(f64::INFINITY),
        })
    }
}

/// [`FaceArrows`] for one world: per coupling, whether its arrows are drawn, and when.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct DrawnFaces {
    contacts: Vec<bool>,
    from: f64,
    until: f64,
}

impl DrawnFaces {
    /// Whether coupling `index`'s arrows are drawn at the simulated time `time` [s].
    fn drawn(&self, index: usize, time: f64) -> bool {
        self.contacts.get(index).copied().unwrap_or(false) && (self.from..=self.until).contains(&time)
    }
}

/// One contact's buffered arrows: a row at some frames only.
struct ContactArrows {
    /// Coupling index in the world.
    index: usize,
    path: String,
    /// The frames with a row, the arrows in each, and their origins and vectors.
    frames: Vec<usize>,
    counts: Vec<usize>,
    origins: Vec<[f32; 3]>,
    vectors: Vec<[f32; 3]>,
    /// Whether the last row sent or buffered drew arrows (an empty row clears them when the
    /// contact stops being drawn).
    showing: bool,
    /// Whether the arrows' colour has been logged (statically, with the contact's first rows:
    /// a contact never drawn costs the recording nothing).
    coloured: bool,
}

/// Every contact's arrows.
pub(super) struct FaceArrowTrack {
    contacts: Vec<ContactArrows>,
}

impl FaceArrowTrack {
    /// The world's contacts (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let contacts: Vec<ContactArrows> = world
            .couplings()
            .iter()
            .enumerate()
            .filter(|(_, coupling)| matches!(coupling.kind, CouplingKind::Contact(_)))
            .map(|(index, coupling)| ContactArrows {
                index,
                path: paths::coupling(coupling),
                frames: Vec::new(),
                counts: Vec::new(),
                origins: Vec::new(),
                vectors: Vec::new(),
                showing: false,
                coloured: false,
            })
            .collect();
        (!contacts.is_empty()).then_some(Self { contacts })
    }

    pub(super) fn len(&self) -> usize {
        self.contacts.len()
    }
}

impl Track for FaceArrowTrack {
    fn capture(&mut self, world: &World, frame: usize, settings: &Settings) -> usize {
        let mut bytes = 0;
        for arrows in &mut self.contacts {
            let drawn = settings.face_arrows.drawn(arrows.index, world.time());
            if !drawn && !arrows.showing {
                continue;
            }
            let count = match (&world.couplings()[arrows.index].kind, drawn) {
                (CouplingKind::Contact(contact), true) => {
                    face_arrows(world, contact, &mut arrows.origins, &mut arrows.vectors)
                }
                _ => 0,
            };
            arrows.frames.push(frame);
            arrows.counts.push(count);
            arrows.showing = drawn;
            bytes += count * 2 * 3 * 4;
        }
        bytes
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        for arrows in self.contacts.iter_mut().filter(|arrows| !arrows.frames.is_empty()) {
            if !arrows.coloured {
                let [r, g, b] = ARROW_RGB;
                stream.log_static(
                    arrows.path.as_str(),
                    &rerun::Arrows3D::update_fields().with_colors([rerun::Color::from_rgb(r, g, b)]),
                )?;
                arrows.coloured = true;
            }
            let drawn = vec![
                column(
                    rerun::Arrows3D::descriptor_vectors(),
                    floats(arrows.vectors.drain(..)),
                    arrows.counts.iter().copied(),
                ),
                column(
                    rerun::Arrows3D::descriptor_origins(),
                    floats(arrows.origins.drain(..)),
                    arrows.counts.iter().copied(),
                ),
            ];
            let times = frames.columns_of(arrows.frames.iter().copied());
            send_chunk(stream, &arrows.path, times, drawn, sent)?;
            arrows.frames.clear();
            arrows.counts.clear();
        }
        Ok(())
    }
}

/// Appends `contact`'s face forces above the threshold, as world arrows from the face
/// centroids, the largest one body radius long; returns how many.
fn face_arrows(world: &World, contact: &Contact, origins: &mut Vec<[f32; 3]>, vectors: &mut Vec<[f32; 3]>) -> usize {
    let body = &world.bodies()[contact.body()];
    let weight = body.mass() * world.gravity().norm().max(1.0);
    let faces: Vec<_> = contact
        .active_faces(world.frames())
        .into_iter()
        .filter(|face| face.force.norm() > ARROW_THRESHOLD * weight)
        .collect();
    let largest = faces.iter().map(|face| face.force.norm()).fold(0.0, f64::max);
    let scale = contact.boundary().bounding_radius() / largest.max(f64::MIN_POSITIVE);
    let frame = &world.frames()[contact.body()];
    for face in &faces {
        origins.push(f32x3(&(frame.position + frame.rotation * face.centroid)));
        vectors.push(f32x3(&(frame.rotation * face.force * scale)));
    }
    faces.len()
}
