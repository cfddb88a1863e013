//! What the window renders with, and what the viewer may keep (docs/window.md, "Memory").
//!
//! - On a software rasterizer (Mesa's lavapipe on a machine without a GPU: a VM, a remote
//!   desktop, Xvfb) the panel's log says so once, and, below [`FIXED_MESA`], that the driver
//!   leaks while the viewer plays and how to get the newer one.
//! - The embedded viewer keeps at most [`LIVE_DATA_BUDGET`] of heap above what the program held
//!   when it started (counted by Rerun's accounting allocator, `main.rs`): past it, Rerun's viewer
//!   drops the oldest data of the live run (the `--save` file keeps everything), so a long
//!   session does not grow without end.

use rerun::external::eframe::egui_wgpu::wgpu;
use rerun::external::re_memory::{MemoryLimit, MemoryUse};

/// The first Mesa major release whose lavapipe was measured not to leak while the viewer plays
/// (25.0.7 from Debian bookworm-backports; 22.3.6, Debian 12's own, grows by about 14 MB a second
/// on `moored_buoy`).
pub const FIXED_MESA: u32 = 25;

/// Heap the viewer may add to what the program held when it started [bytes]: about two minutes of
/// `moored_buoy` at ×1 (the live recording's data held by the viewer grows by 0.5 MB a second).
pub const LIVE_DATA_BUDGET: u64 = 64 * 1024 * 1024;

/// The viewer's memory limit: the heap the program holds now (its resident size where the heap is
/// not counted) plus [`LIVE_DATA_BUDGET`].
pub fn memory_limit() -> MemoryLimit {
    MemoryLimit::from_bytes(MemoryUse::capture().used().unwrap_or(0) + LIVE_DATA_BUDGET)
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
    match mesa_major(driver_info) {
        Some(major) if major < FIXED_MESA => Some(format!(
            "{rendering}; this Mesa's lavapipe leaks memory while playing (docs/window.md, \"Memory\"): \
             scripts/setup.sh installs Mesa {FIXED_MESA} from bookworm-backports (ensure_cpu_vulkan_driver)"
        )),
        Some(_) | None => Some(rendering),
    }
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
    fn an_old_lavapipe_is_named_with_its_fix_a_new_one_as_slow_a_gpu_not_at_all() {
        let old = note_for(wgpu::DeviceType::Cpu, LLVMPIPE, "Mesa 22.3.6 (LLVM 15.0.6)").unwrap();
        assert!(old.contains("Mesa 22.3.6") && old.contains("leaks") && old.contains("bookworm-backports"), "{old}");
        let new = note_for(wgpu::DeviceType::Cpu, LLVMPIPE, "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)").unwrap();
        assert!(new.contains("on the CPU") && !new.contains("leaks"), "{new}");
        assert_eq!(note_for(wgpu::DeviceType::DiscreteGpu, "AMD Radeon", "Mesa 22.3.6"), None);
        assert_eq!(mesa_major("Mesa 22.3.6 (LLVM 15.0.6)"), Some(22));
        assert_eq!(mesa_major("NVIDIA 550.54"), None);
    }
}
