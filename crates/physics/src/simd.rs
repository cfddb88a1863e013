//! Which vector instructions the processor has, for the stages built more than once.
//!
//! The couplings stage ([`crate::system`]) and the leapfrog step ([`crate::integrator::leapfrog`])
//! are compiled three times: for AVX-512 (with AVX2 and FMA: the Ice Lake / Zen 4 feature set),
//! for AVX2 with FMA, and for the SSE2 every x86-64 has; [`Level::best`] picks one at run time.
//! The arithmetic is the same IEEE arithmetic in every build (no fused multiply–add is
//! introduced: Rust never contracts `a * b + c`), so the results are too, bit for bit; a test
//! runs every build the processor has on the same states and compares.

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
    #[inline]
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
