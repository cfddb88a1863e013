//! A group of knobs over values of the scene file (the couplings, the water, each body's water
//! coefficients): what each knob shows, accepted or not, and why it was refused; an edited one
//! checked by the scene builder into the tuned scene; all of them back to what the file says.
//! No egui in it, and no check of its own: a value is what the [`Group`]'s build says it is.

use super::simulation::Command;
use tether_scene::SceneFile;
use tether_scene::build::Bodies;

/// Where a group's values are in a scene file and how the scene builder turns one into the
/// command that applies it to the running simulation — or why it refuses it (`R`, shown as the
/// builder words it). Knob `index` is value `index` of `values`.
pub struct Group<D, R> {
    /// The group's values in a scene file, in knob order.
    pub values: fn(&SceneFile) -> Vec<D>,
    /// Value `index` of a scene file set to this.
    pub put: fn(&mut SceneFile, usize, D),
    /// Value `index` of a candidate scene, checked and built against the scene's bodies.
    pub build: fn(&SceneFile, usize, &mut Bodies) -> Result<Command, R>,
}

/// One knob: what it shows (accepted or not) and why that was refused.
#[derive(Debug, Clone, PartialEq)]
pub struct Knob<D, R> {
    pub draft: D,
    pub refusal: Option<R>,
}

/// The knobs of one [`Group`].
pub struct Knobs<D: 'static, R: 'static> {
    group: &'static Group<D, R>,
    knobs: Vec<Knob<D, R>>,
}

impl<D: Clone + PartialEq + 'static, R: 'static> Knobs<D, R> {
    /// The knobs of `group`, showing what `file` says.
    pub fn of(group: &'static Group<D, R>, file: &SceneFile) -> Self {
        let knobs = (group.values)(file).into_iter().map(|draft| Knob { draft, refusal: None }).collect();
        Self { group, knobs }
    }

    /// The knobs, to draw and edit.
    pub fn knobs(&self) -> &[Knob<D, R>] {
        &self.knobs
    }

    /// The knobs, to draw and edit (an edited one is then [`tune`](Self::tune)d).
    pub fn knobs_mut(&mut self) -> &mut [Knob<D, R>] {
        &mut self.knobs
    }

    /// Knob `index` shows what `file` says (a fit's values; then [`tune`](Self::tune) it).
    pub fn show(&mut self, index: usize, file: &SceneFile) {
        let value = (self.group.values)(file).into_iter().nth(index);
        if let (Some(knob), Some(value)) = (self.knobs.get_mut(index), value) {
            knob.draft = value;
        }
    }

    /// Checks knob `index`'s draft with the scene builder, in `tuned` with its other values: an
    /// accepted value goes into `tuned` and comes back as the command that applies it; a
    /// refused one stays in its knob with the reason, `tuned` untouched.
    pub fn tune(&mut self, index: usize, tuned: &mut SceneFile, bodies: &mut Bodies) -> Option<Command> {
        let knob = self.knobs.get_mut(index)?;
        let mut candidate = tuned.clone();
        (self.group.put)(&mut candidate, index, knob.draft.clone());
        match (self.group.build)(&candidate, index, bodies) {
            Ok(command) => {
                knob.refusal = None;
                *tuned = candidate;
                Some(command)
            }
            Err(refusal) => {
                knob.refusal = Some(refusal);
                None
            }
        }
    }

    /// Every knob back to what `file` says; returns the knobs to [`tune`](Self::tune) again for
    /// the running simulation to follow: those whose value in `tuned` is not the file's, and
    /// those refused.
    pub fn revert(&mut self, file: &SceneFile, tuned: &SceneFile) -> Vec<usize> {
        let values = (self.group.values)(file).into_iter().zip((self.group.values)(tuned));
        let mut again = Vec::new();
        for (index, (knob, (value, running))) in self.knobs.iter_mut().zip(values).enumerate() {
            if value != running || knob.refusal.is_some() {
                again.push(index);
            }
            knob.draft = value;
        }
        again
    }
}
