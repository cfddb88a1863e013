//! Which vector instructions the processor has, and the one dispatch of the stages built more
//! than once.
//!
//! The couplings stage ([`crate::system`]), the water stage ([`crate::water_stage`]) and the
//! leapfrog step ([`crate::integrator::leapfrog`]) are compiled three times: for AVX-512 (with
//! AVX2 and FMA: the Ice Lake / Zen 4 feature set), for AVX2 with FMA, and for the SSE2 every
//! x86-64 has; [`Level::best`] picks one at run time. The arithmetic is the same IEEE arithmetic
//! in every build (no fused multiply–add is introduced: Rust never contracts `a * b + c`), so the
//! results are too, bit for bit; a test runs every build the processor has on the same states
//! and compares.
//!
//! Each stage goes through [`SupportedLevel::run`], which calls it inside a function compiled
//! for the level's instructions: the stage, an `#[inline(always)]` closure over
//! `#[inline(always)]` functions, is compiled into each of them. This is hand-written rather than
//! the `multiversion` crate's dispatch, which picks the build by itself from the processor's
//! features: here the system holds the level it runs, so that a test can run every build the
//! processor has on the same states (`System::use_level`), and a [`SupportedLevel`] can only be
//! made for a level the processor has, which is what makes the dispatch safe.

/// A set of vector instructions a stage is built for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    /// AVX-512F and AVX-512VL, with AVX2 and FMA: 32 vector registers.
    Avx512,
    /// AVX2 and FMA: four `f64` to an instruction.
    Avx2,
    /// What every processor of the target has (SSE2 on x86-64).
    Portable,
}

impl Level {
    /// The widest level this processor has (the detection is cached by the standard library).
    pub fn best() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            let avx2 = std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma");
            if avx2 && std::arch::is_x86_feature_detected!("avx512f") && std::arch::is_x86_feature_detected!("avx512vl")
            {
                return Self::Avx512;
            }
            if avx2 {
                return Self::Avx2;
            }
        }
        Self::Portable
    }

    /// Every level this processor can run, widest first (tests compare them).
    pub fn available() -> Vec<Self> {
        [Self::Avx512, Self::Avx2, Self::Portable].into_iter().filter(|level| level.supported()).collect()
    }

    /// Whether this processor can run code built for the level.
    pub fn supported(self) -> bool {
        match self {
            Self::Portable => true,
            Self::Avx2 => matches!(Self::best(), Self::Avx2 | Self::Avx512),
            Self::Avx512 => Self::best() == Self::Avx512,
        }
    }
}

/// A [`Level`] this processor has: the only way to run a build of a stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SupportedLevel(Level);

impl SupportedLevel {
    /// The widest level this processor has.
    pub fn best() -> Self {
        Self(Level::best())
    }

    /// `level`, if this processor has it.
    pub fn new(level: Level) -> Option<Self> {
        level.supported().then_some(Self(level))
    }

    pub fn level(self) -> Level {
        self.0
    }

    /// `stage()` compiled for this level. `stage` must be an `#[inline(always)]` closure (over
    /// `#[inline(always)]` functions, down to the arithmetic that is to use the level's
    /// instructions): what is not inlined into the build is compiled for the portable level.
    #[inline(always)]
    pub fn run<R>(self, stage: impl FnOnce() -> R) -> R {
        match self.0 {
            // SAFETY (both): a `SupportedLevel` is only made for a level the processor has
            // (`SupportedLevel::new` checks; `Level::best` is one), whose features these builds
            // enable.
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => unsafe { avx512(stage) },
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => unsafe { avx2(stage) },
            // Never made off x86-64, where `Level::best` is the portable level.
            #[cfg(not(target_arch = "x86_64"))]
            Level::Avx512 | Level::Avx2 => stage(),
            Level::Portable => stage(),
        }
    }
}

/// `stage()` built for AVX-512 (with AVX2 and FMA).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
fn avx512<R>(stage: impl FnOnce() -> R) -> R {
    stage()
}

/// `stage()` built for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn avx2<R>(stage: impl FnOnce() -> R) -> R {
    stage()
}
