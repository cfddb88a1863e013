//! What a recorder has done: frames, rows and bytes sent per kind of entity.

/// Bytes of a row's index in a chunk: its row id (16) and its two timelines (8 each).
pub const ROW_INDEX_BYTES: u64 = 16 + 8 + 8;

/// What a recorder has sent since it started.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordStats {
    /// Frames captured.
    pub frames: u64,
    /// Per kind of entity, in the order they are recorded.
    pub kinds: Vec<KindStats>,
}

/// What one kind of entity has sent.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct KindStats {
    /// `bodies`, `springs`, … (see the crate's recording layout).
    pub kind: &'static str,
    /// Entities of this kind.
    pub entities: usize,
    /// Temporal rows sent (one per entity and frame it is logged at).
    pub rows: u64,
    /// Arrow bytes sent, before compression: the component columns and
    /// [`ROW_INDEX_BYTES`] per row.
    pub bytes: u64,
}

impl RecordStats {
    /// Arrow bytes sent per frame, all kinds together.
    pub fn bytes_per_frame(&self) -> f64 {
        self.kinds.iter().map(|kind| kind.bytes).sum::<u64>() as f64 / self.frames.max(1) as f64
    }
}

impl KindStats {
    /// Arrow bytes sent per frame captured (`frames`).
    pub fn bytes_per_frame(&self, frames: u64) -> f64 {
        self.bytes as f64 / frames.max(1) as f64
    }
}
