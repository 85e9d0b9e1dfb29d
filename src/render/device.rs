//! Opening a GPU device: the backend choice, the adapter search and what the device offers.
//!
//! Backend choice, in order of precedence: the `backend` argument, the `TOONMESH_BACKEND`
//! environment variable, then `auto` (Vulkan first, then GL through EGL). Both APIs are loaded
//! at run time by wgpu, so nothing links against Vulkan or EGL.

use std::sync::Arc;

use crate::error::{Error, Result};

/// The environment variable that picks a backend when no argument does.
pub const BACKEND_ENV: &str = "TOONMESH_BACKEND";

/// Colour is stored as sRGB: shading happens in linear light and the target encodes on store.
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BackendChoice {
    /// Vulkan if a device opens there, else GL.
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

    /// The names `parse` takes first, in the order of the variants.
    pub const NAMES: [&'static str; 3] = ["auto", "vulkan", "gl"];

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

/// What `gpu_info()` reports.
#[derive(Clone, Debug, serde::Serialize)]
pub struct GpuInfo {
    pub name: String,
    pub backend: &'static str,
    pub device_type: String,
    pub driver: String,
    pub driver_info: String,
    pub max_texture_size: u32,
    pub msaa_samples: Vec<u32>,
    /// Whether passes are timed on the GPU (timestamp queries).
    pub timestamps: bool,
}

/// An open device with its queue and what it offers.
pub struct Device {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub info: GpuInfo,
    pub limits: wgpu::Limits,
    /// The GL backend cannot bind a multisampled texture for sampling, nor render to 32-bit
    /// float formats; passes consult this.
    pub is_gl: bool,
}

pub fn no_adapter(tried: &str) -> Error {
    Error::NoAdapter(format!(
        "no GPU adapter found (backend: {tried}). toonmesh renders on any Vulkan or OpenGL ES 3 device, \
         including Mesa's software rasterisers. On Debian/Ubuntu install them with \
         `sudo apt-get install mesa-vulkan-drivers libvulkan1` (Vulkan, lavapipe) or \
         `sudo apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri` (GL through EGL, llvmpipe); \
         choose a backend with the backend= argument or {BACKEND_ENV}=vulkan|gl|auto."
    ))
}

impl Device {
    /// Opens a device on one backend (`Vulkan` or `Gl`). An adapter that is found but refuses
    /// to open a device counts as no adapter, so that `auto` moves on to the next backend.
    pub fn open(choice: BackendChoice) -> Result<Device> {
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
        let timestamps = adapter.features().contains(wgpu::Features::TIMESTAMP_QUERY);
        let required_features =
            if timestamps { wgpu::Features::TIMESTAMP_QUERY } else { wgpu::Features::empty() };
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("toonmesh"),
            required_features,
            // Everything the adapter offers: GL adapters are below WebGPU's defaults in places,
            // software adapters above them in texture size.
            required_limits: limits.clone(),
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        }))
        .map_err(|e| {
            Error::NoAdapter(format!("the {} adapter refused to open a device: {e}", choice.name()))
        })?;
        // Errors are caught per render with error scopes; anything outside one must not panic.
        device.on_uncaptured_error(Arc::new(|e| {
            eprintln!("toonmesh: GPU error outside a render: {e}");
        }));
        let a = adapter.get_info();
        let is_gl = a.backend == wgpu::Backend::Gl;
        let color_samples = adapter.get_texture_format_features(COLOR_FORMAT).flags;
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
            timestamps,
        };
        Ok(Device { device, queue, info, limits, is_gl })
    }

    /// Waits until the GPU has finished `submission`.
    pub fn wait(&self, submission: wgpu::SubmissionIndex, what: &str) -> Result<()> {
        self.device
            .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
            .map(|_| ())
            .map_err(|e| Error::Gpu(format!("waiting for the GPU ({what}): {e}")))
    }
}
