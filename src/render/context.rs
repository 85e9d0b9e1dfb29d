//! The process-wide GPU context: a device per backend, created lazily on first use and shared by
//! every render in the process, with the pipelines and frame resources it caches.
//!
//! After `fork()` the child has none of the parent's GPU threads: waiting on the parent's device
//! would never return. A child therefore gets contexts of its own (the parent's are never
//! touched, not even dropped), and work on a context made before the fork fails at once with
//! an error that says so.

use std::collections::HashMap;
use std::mem::ManuallyDrop;
use std::sync::atomic::{AtomicPtr, AtomicU32, Ordering};
use std::sync::{Arc, Mutex};

use crate::error::{Error, Result};

use super::device::{no_adapter, BackendChoice, Device};
use super::graph::resources::FramePool;
use super::pipelines::PipelineCache;

pub struct GpuContext {
    dev: ManuallyDrop<Device>,
    pub pipelines: PipelineCache,
    pub frames: FramePool,
    /// The process that opened the device.
    pid: u32,
}

impl std::ops::Deref for GpuContext {
    type Target = Device;
    fn deref(&self) -> &Device {
        &self.dev
    }
}

impl Drop for GpuContext {
    fn drop(&mut self) {
        // In a forked child the device belongs to the parent: closing it would wait on threads
        // that do not exist here, so it is leaked.
        if self.pid == std::process::id() {
            // SAFETY: dropped once, here, and never used again.
            unsafe { ManuallyDrop::drop(&mut self.dev) }
        }
    }
}

impl GpuContext {
    /// Fails when this context was made by the process this one was forked from.
    pub fn check_process(&self) -> Result<()> {
        if self.pid == std::process::id() {
            return Ok(());
        }
        Err(Error::Gpu(
            "this renderer was made before the process forked, and its GPU device stays with the \
             parent; make a new Renderer in the child (toonmesh.render does so by itself)"
                .into(),
        ))
    }
}

struct Registry {
    pid: u32,
    contexts: Mutex<HashMap<BackendChoice, Arc<GpuContext>>>,
}

static REGISTRY: AtomicPtr<Registry> = AtomicPtr::new(std::ptr::null_mut());

/// This process's registry. A forked child starts a fresh one rather than locking the parent's
/// (another thread may have held that lock when the process forked).
fn registry() -> &'static Registry {
    let pid = std::process::id();
    let current = REGISTRY.load(Ordering::Acquire);
    // SAFETY: registries are leaked, never freed, so a pointer read here stays valid.
    if let Some(r) = unsafe { current.as_ref() } {
        if r.pid == pid {
            return r;
        }
    }
    let fresh = Box::into_raw(Box::new(Registry { pid, contexts: Mutex::new(HashMap::new()) }));
    match REGISTRY.compare_exchange(current, fresh, Ordering::AcqRel, Ordering::Acquire) {
        // SAFETY: just leaked above.
        Ok(_) => unsafe { &*fresh },
        Err(other) => {
            // SAFETY: `fresh` was never shared; `other` is a leaked registry.
            unsafe {
                drop(Box::from_raw(fresh));
                &*other
            }
        }
    }
}

/// The process that opened a GL device (0: none). EGL keeps its display per process and a forked
/// child inherits it half-alive: opening GL again there hangs, so a child refuses at once.
static GL_OPENED_BY: AtomicU32 = AtomicU32::new(0);

fn create(choice: BackendChoice) -> Result<GpuContext> {
    let pid = std::process::id();
    let gl_parent = GL_OPENED_BY.load(Ordering::Acquire);
    if choice == BackendChoice::Gl && gl_parent != 0 && gl_parent != pid {
        return Err(Error::Gpu(
            "the GL backend cannot open in a process forked from one that used it (EGL's state \
             does not survive fork()); use the Vulkan backend in the child, or start workers \
             with the 'spawn' or 'forkserver' method"
                .into(),
        ));
    }
    let dev = Device::open(choice)?;
    if dev.is_gl {
        GL_OPENED_BY.store(pid, Ordering::Release);
    }
    Ok(GpuContext {
        pipelines: PipelineCache::new(&dev.device),
        frames: FramePool::default(),
        dev: ManuallyDrop::new(dev),
        pid: std::process::id(),
    })
}

/// The shared context for `choice`, created on first use.
pub fn context(choice: BackendChoice) -> Result<Arc<GpuContext>> {
    let mut map = registry().contexts.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(ctx) = map.get(&choice) {
        return Ok(ctx.clone());
    }
    let ctx = match choice {
        BackendChoice::Vulkan | BackendChoice::Gl => Arc::new(create(choice)?),
        BackendChoice::Auto => {
            let found =
                [BackendChoice::Vulkan, BackendChoice::Gl].into_iter().find_map(|b| match map.get(&b) {
                    Some(c) => Some(Ok(c.clone())),
                    None => match create(b) {
                        Ok(c) => Some(Ok(Arc::new(c))),
                        Err(Error::NoAdapter(_)) => None,
                        Err(e) => Some(Err(e)),
                    },
                });
            match found {
                Some(c) => c?,
                None => return Err(no_adapter("auto (Vulkan, then GL)")),
            }
        }
    };
    let concrete = if ctx.is_gl { BackendChoice::Gl } else { BackendChoice::Vulkan };
    map.insert(concrete, ctx.clone());
    map.insert(choice, ctx.clone());
    Ok(ctx)
}
