//! The process-wide GPU context: instance, adapter, device and queue, created lazily on first
//! use and shared by every render in the process (one per backend that was asked for).
//!
//! Backend choice, in order of precedence: the `backend` argument, the `TOONMESH_BACKEND`
//! environment variable, then `auto` (Vulkan first, then GL through EGL). Both APIs are loaded
//! at run time by wgpu, so nothing links against Vulkan or EGL.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use crate::error::{Error, Result};

use super::pipelines::PipelineCache;
use super::targets::TargetPool;

/// The environment variable that picks a backend when no argument does.
pub const BACKEND_ENV: &str = "TOONMESH_BACKEND";

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BackendChoice {
    /// Vulkan if an adapter is found there, else GL.
    Auto,
    Vulkan,
    Gl,
}

impl BackendChoice {
    pub fn parse(arg: &str, s: &str) -> Result<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "" | "auto" => Ok(Self::Auto),
            "vulkan" | "vk" => Ok(Self::Vulkan),
            "gl" | "gles" | "opengl" | "egl" => Ok(Self::Gl),
            other => {
                Err(Error::invalid(arg, format!("unknown backend {other:?}; use 'auto', 'vulkan' or 'gl'")))
            }
        }
    }

    /// The argument if given, else the environment variable, else `Auto`.
    pub fn resolve(arg: Option<&str>) -> Result<Self> {
        match arg {
            Some(s) => Self::parse("backend", s),
            None => match std::env::var(BACKEND_ENV) {
                Ok(s) => Self::parse(BACKEND_ENV, &s),
                Err(_) => Ok(Self::Auto),
            },
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Vulkan => "vulkan",
            Self::Gl => "gl",
        }
    }
}

/// What `gpu_info()` reports.
#[derive(Clone, Debug)]
pub struct GpuInfo {
    pub name: String,
    pub backend: &'static str,
    pub device_type: String,
    pub driver: String,
    pub driver_info: String,
    pub max_texture_size: u32,
    pub msaa_samples: Vec<u32>,
}

pub struct GpuContext {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub info: GpuInfo,
    pub limits: wgpu::Limits,
    pub pipelines: PipelineCache,
    pub targets: TargetPool,
    /// The GL backend cannot bind a multisampled texture for sampling, nor give more than the
    /// formats its GLES context offers; passes consult this.
    pub is_gl: bool,
}

static CONTEXTS: Mutex<Option<HashMap<BackendChoice, Arc<GpuContext>>>> = Mutex::new(None);

/// The shared context for `choice`, created on first use.
pub fn context(choice: BackendChoice) -> Result<Arc<GpuContext>> {
    let mut guard = CONTEXTS.lock().unwrap_or_else(|e| e.into_inner());
    let map = guard.get_or_insert_with(HashMap::new);
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

fn no_adapter(tried: &str) -> Error {
    Error::NoAdapter(format!(
        "no GPU adapter found (backend: {tried}). toonmesh renders on any Vulkan or OpenGL ES 3 device, \
         including Mesa's software rasterisers. On Debian/Ubuntu install them with \
         `sudo apt-get install mesa-vulkan-drivers libvulkan1` (Vulkan, lavapipe) or \
         `sudo apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri` (GL through EGL, llvmpipe); \
         choose a backend with the backend= argument or {BACKEND_ENV}=vulkan|gl|auto."
    ))
}

fn create(choice: BackendChoice) -> Result<GpuContext> {
    let backends = match choice {
        BackendChoice::Vulkan => wgpu::Backends::VULKAN,
        BackendChoice::Gl => wgpu::Backends::GL,
        BackendChoice::Auto => wgpu::Backends::VULKAN | wgpu::Backends::GL,
    };
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    desc.flags = wgpu::InstanceFlags::from_build_config().with_env();
    desc.backend_options = wgpu::BackendOptions::from_env_or_default();
    let instance = wgpu::Instance::new(desc);
    let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        force_fallback_adapter: false,
        compatible_surface: None,
        apply_limit_buckets: false,
    }))
    .map_err(|_| no_adapter(choice.name()))?;
    let limits = adapter.limits();
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("toonmesh"),
        required_features: wgpu::Features::empty(),
        // Everything the adapter offers: GL adapters are below WebGPU's defaults in places,
        // software adapters above them in texture size.
        required_limits: limits.clone(),
        experimental_features: wgpu::ExperimentalFeatures::disabled(),
        memory_hints: wgpu::MemoryHints::Performance,
        trace: wgpu::Trace::Off,
    }))
    .map_err(|e| Error::NoAdapter(format!("the {} adapter refused to open a device: {e}", choice.name())))?;
    // Errors are caught per render with error scopes; anything outside one must not panic.
    device.on_uncaptured_error(Arc::new(|e| {
        eprintln!("toonmesh: GPU error outside a render: {e}");
    }));
    let a = adapter.get_info();
    let is_gl = a.backend == wgpu::Backend::Gl;
    let color_samples = adapter.get_texture_format_features(super::targets::COLOR_FORMAT).flags;
    let msaa_samples = [1u32, 2, 4, 8, 16]
        .into_iter()
        .filter(|&s| s == 1 || color_samples.sample_count_supported(s))
        .collect();
    let info = GpuInfo {
        name: a.name.clone(),
        backend: if is_gl { "gl" } else { "vulkan" },
        device_type: format!("{:?}", a.device_type).to_ascii_lowercase(),
        driver: a.driver.clone(),
        driver_info: a.driver_info.clone(),
        max_texture_size: limits.max_texture_dimension_2d,
        msaa_samples,
    };
    Ok(GpuContext {
        pipelines: PipelineCache::new(&device),
        targets: TargetPool::default(),
        device,
        queue,
        info,
        limits,
        is_gl,
    })
}
