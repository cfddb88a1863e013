//! What the window renders with, and what the viewer may keep (docs/window.md, "Memory").
//!
//! - On a software rasterizer (Mesa's lavapipe on a machine without a GPU: a VM, a remote
//!   desktop, Xvfb) the panel's log says so once, and, below [`FIXED_MESA`], a banner above the
//!   viewer says that the driver leaks while the viewer plays and the command that installs the
//!   newer one ([`leak_banner`]).
//! - The embedded viewer keeps at most [`LIVE_DATA_BUDGET`] of heap above what the program held
//!   when it started (counted by Rerun's accounting allocator, `main.rs`): past it, Rerun's viewer
//!   drops the oldest data of the live run (the `--save` file keeps everything), so a long
//!   session does not grow without end.
//! - On a software rasterizer the window draws at most [`CPU_MAX_FPS`] frames a second
//!   ([`FrameCap`]): the viewer redraws every frame while a run plays, and on the CPU each frame
//!   takes the core the simulation needs.

use rerun::external::eframe::egui_wgpu::wgpu;
use rerun::external::re_memory::{MemoryLimit, MemoryUse};
use std::time::{Duration, Instant};

/// The first Mesa major release whose lavapipe was measured not to leak while the viewer plays
/// (25.0.7 from Debian bookworm-backports; 22.3.6, Debian 12's own, grows by about 14 MB a second
/// on `moored_buoy`).
pub const FIXED_MESA: u32 = 25;

/// Heap the viewer may add to what the program held when it started [bytes]: about a minute of
/// `moored_buoy` at ×1 (the live recording's data held by the viewer grows by about 0.45 MB a
/// second), so the window's memory is flat after the first minute of play.
pub const LIVE_DATA_BUDGET: u64 = 32 * 1024 * 1024;

/// The viewer's memory limit: the heap the program holds now (its resident size where the heap is
/// not counted) plus [`LIVE_DATA_BUDGET`].
pub fn memory_limit() -> MemoryLimit {
    MemoryLimit::from_bytes(MemoryUse::capture().used().unwrap_or(0) + LIVE_DATA_BUDGET)
}

/// Frames a second drawn at most when the viewer renders on the CPU (`tether gui --max-fps`
/// changes it): a 3D view and its plots stay fluid to the eye, and an idle machine's renderer
/// does not draw faster than that at the simulation's expense (on a busy one it draws slower
/// anyway: the window took 25 s of CPU per minute of play capped and uncapped alike,
/// docs/window.md, "Memory").
pub const CPU_MAX_FPS: u32 = 30;

/// A cap on the frame rate: each frame starts no sooner than the shortest interval after the
/// last (the window waits out the rest, as a display's vertical sync makes it wait on a GPU).
pub struct FrameCap {
    /// The shortest time between the starts of two frames.
    interval: Duration,
    /// When the last frame started.
    last: Instant,
}

impl FrameCap {
    /// At most `max_fps` frames a second; `None` when neither `max_fps` is given nor the
    /// adapter `info` renders on the CPU ([`CPU_MAX_FPS`] there).
    pub fn for_adapter(max_fps: Option<u32>, info: Option<&wgpu::AdapterInfo>) -> Option<Self> {
        Self::at_most(max_fps, info.is_some_and(|info| info.device_type == wgpu::DeviceType::Cpu))
    }

    /// At most `max_fps` frames a second, or [`CPU_MAX_FPS`] when not given and `on_cpu`.
    fn at_most(max_fps: Option<u32>, on_cpu: bool) -> Option<Self> {
        let fps = max_fps.or(on_cpu.then_some(CPU_MAX_FPS))?;
        Some(Self { interval: Duration::from_secs_f64(1.0 / f64::from(fps.max(1))), last: Instant::now() })
    }

    /// Waits until a frame may start, then counts it as started.
    pub fn wait(&mut self) {
        let since = self.last.elapsed();
        if since < self.interval {
            std::thread::sleep(self.interval - since);
        }
        self.last = Instant::now();
    }
}

/// The line the panel's log shows once for the adapter `info`: `None` on a GPU.
pub fn software_note(info: &wgpu::AdapterInfo) -> Option<String> {
    note_for(info.device_type, &info.name, &info.driver_info)
}

/// [`software_note`] for an adapter of type `device_type`, named `name`, its driver described
/// by `driver_info`.
fn note_for(device_type: wgpu::DeviceType, name: &str, driver_info: &str) -> Option<String> {
    if device_type != wgpu::DeviceType::Cpu {
        return None;
    }
    let rendering = format!("the viewer renders on the CPU ({name}, {driver_info}): expect a slow view");
    match leaking_mesa(device_type, driver_info) {
        Some(_) => Some(format!(
            "{rendering}; this Mesa's lavapipe leaks memory while playing (docs/window.md, \"Memory\"): \
             scripts/setup.sh installs Mesa {FIXED_MESA} from bookworm-backports (ensure_cpu_vulkan_driver)"
        )),
        None => Some(rendering),
    }
}

/// The command that installs the lavapipe that does not leak on Debian 12, from the repository's
/// folder (what `scripts/run` does before it opens the window).
pub const FIX_COMMAND: &str = "bash -c 'source scripts/setup.sh && ensure_cpu_vulkan_driver'";

/// The banner the window shows above the viewer for the adapter `info` when its driver leaks
/// while the viewer plays (Mesa's lavapipe before [`FIXED_MESA`]), in full, with the command
/// that fixes it; `None` for any other adapter.
pub fn leak_banner(info: &wgpu::AdapterInfo) -> Option<String> {
    banner_for(info.device_type, &info.driver_info)
}

/// [`leak_banner`] for an adapter of type `device_type` whose driver is `driver_info`.
fn banner_for(device_type: wgpu::DeviceType, driver_info: &str) -> Option<String> {
    let major = leaking_mesa(device_type, driver_info)?;
    Some(format!(
        "This window renders on the CPU with Mesa {major}'s lavapipe ({driver_info}), which leaks about 14 MB a \
         second while the viewer plays (9.5 GB after 9 minutes; docs/window.md, \"Memory\"). Mesa {FIXED_MESA} \
         does not: close the window, run  {FIX_COMMAND}  in Tether's folder (scripts/run does it for you), and \
         open it again."
    ))
}

/// The Mesa major version of a CPU adapter's lavapipe that leaks while the viewer plays (below
/// [`FIXED_MESA`]); `None` for any other adapter or driver.
fn leaking_mesa(device_type: wgpu::DeviceType, driver_info: &str) -> Option<u32> {
    mesa_major(driver_info).filter(|&major| device_type == wgpu::DeviceType::Cpu && major < FIXED_MESA)
}

/// The major version in a driver description such as `Mesa 22.3.6 (LLVM 15.0.6)`.
fn mesa_major(driver_info: &str) -> Option<u32> {
    let after = driver_info.split("Mesa ").nth(1)?;
    after.split('.').next()?.trim().parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    const LLVMPIPE: &str = "llvmpipe (LLVM 15.0.6, 256 bits)";

    #[test]
    fn the_cpu_renderer_is_capped_at_30_fps_a_gpu_only_when_asked() {
        let interval = |cap: Option<FrameCap>| cap.map(|cap| cap.interval);
        assert_eq!(interval(FrameCap::at_most(None, true)), Some(Duration::from_secs_f64(1.0 / 30.0)));
        assert_eq!(interval(FrameCap::at_most(None, false)), None);
        assert_eq!(interval(FrameCap::at_most(Some(10), false)), Some(Duration::from_millis(100)));
        assert_eq!(interval(FrameCap::at_most(Some(120), true)), Some(Duration::from_secs_f64(1.0 / 120.0)));
    }

    /// Three frames through a 50 fps cap take at least the two intervals between them.
    #[test]
    fn frames_through_the_cap_are_at_least_its_interval_apart() {
        let mut cap = FrameCap::at_most(Some(50), false).unwrap();
        let start = Instant::now();
        for _ in 0..3 {
            cap.wait();
        }
        assert!(start.elapsed() >= Duration::from_millis(40), "{:?}", start.elapsed());
    }

    #[test]
    fn an_old_lavapipe_is_named_with_its_fix_a_new_one_as_slow_a_gpu_not_at_all() {
        let old = note_for(wgpu::DeviceType::Cpu, LLVMPIPE, "Mesa 22.3.6 (LLVM 15.0.6)").unwrap();
        assert!(old.contains("Mesa 22.3.6") && old.contains("leaks") && old.contains("bookworm-backports"), "{old}");
        let new = note_for(wgpu::DeviceType::Cpu, LLVMPIPE, "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)").unwrap();
        assert!(new.contains("on the CPU") && !new.contains("leaks"), "{new}");
        assert_eq!(note_for(wgpu::DeviceType::DiscreteGpu, "AMD Radeon", "Mesa 22.3.6"), None);
        assert_eq!(mesa_major("Mesa 22.3.6 (LLVM 15.0.6)"), Some(22));
        assert_eq!(mesa_major("NVIDIA 550.54"), None);
    }

    /// Issue 47: the leak was said only in a log line cut off mid-sentence; on the leaking
    /// lavapipe the window has a banner with the command that fixes it, on any other adapter none.
    #[test]
    fn the_leaking_lavapipe_gets_a_banner_with_its_fix() {
        let banner = banner_for(wgpu::DeviceType::Cpu, "Mesa 22.3.6 (LLVM 15.0.6)").unwrap();
        assert!(banner.contains("Mesa 22's lavapipe (Mesa 22.3.6 (LLVM 15.0.6)), which leaks"), "{banner}");
        assert!(banner.contains(FIX_COMMAND), "{banner}");
        assert_eq!(banner_for(wgpu::DeviceType::Cpu, "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"), None);
        assert_eq!(banner_for(wgpu::DeviceType::DiscreteGpu, "Mesa 22.3.6"), None);
        assert_eq!(banner_for(wgpu::DeviceType::Cpu, "SwiftShader driver"), None);
    }
}
