//! The renderer's WGSL as GLSL ES 3.00 (WebGL2), by naga's GLSL writer: the pipeline constants
//! written in (`pipeline_constants::process_overrides`), the coordinates adjusted to GL's (y up,
//! depth from -1 to 1: the writer's `ADJUST_COORDINATE_SPACE`, as wgpu's GL backend does, so
//! that a GL framebuffer holds the rows top first, as wgpu's targets do), and the names under
//! which each stage declares its uniform blocks and its textures, with their WGSL group and
//! binding, so that a GL program binds them.

use naga::back::glsl;
use naga::valid::{Capabilities, ValidationFlags, Validator};
use serde::Serialize;

use crate::error::{Error, Result};

/// A resource a stage reads: its name in the GLSL and its WGSL group and binding.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Binding {
    pub name: String,
    pub group: u32,
    pub binding: u32,
}

/// One stage in GLSL ES 3.00.
#[derive(Clone, Debug, Serialize)]
pub struct GlslStage {
    pub source: String,
    /// The uniform blocks.
    pub blocks: Vec<Binding>,
    /// The samplers (a texture combined with its sampler, under the texture's binding).
    pub textures: Vec<Binding>,
}

/// A GL program: its vertex and fragment stages.
#[derive(Clone, Debug, Serialize)]
pub struct GlslProgram {
    pub name: String,
    pub vertex: GlslStage,
    pub fragment: GlslStage,
}

fn glsl_error(what: &str, e: impl std::fmt::Display) -> Error {
    Error::Internal(format!("translating {what} to GLSL ES 3.00: {e}"))
}

/// The parsed and validated module of `wgsl`.
pub fn parse(name: &str, wgsl: &str) -> Result<(naga::Module, naga::valid::ModuleInfo)> {
    let module = naga::front::wgsl::parse_str(wgsl).map_err(|e| glsl_error(name, e.emit_to_string(wgsl)))?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::all())
        .validate(&module)
        .map_err(|e| glsl_error(name, e.emit_to_string(wgsl)))?;
    Ok((module, info))
}

/// Entry point `entry` of `stage` in GLSL ES 3.00, with `constants` written in.
pub fn stage(
    name: &str,
    module: &naga::Module,
    info: &naga::valid::ModuleInfo,
    stage: naga::ShaderStage,
    entry: &str,
    constants: &[(&str, f64)],
) -> Result<GlslStage> {
    let constants: naga::back::PipelineConstants =
        constants.iter().map(|(k, v)| (k.to_string(), *v)).collect();
    let (module, info) =
        naga::back::pipeline_constants::process_overrides(module, info, Some((stage, entry)), &constants)
            .map_err(|e| glsl_error(name, e))?;
    let options = glsl::Options {
        version: glsl::Version::Embedded { version: 300, is_webgl: true },
        writer_flags: glsl::WriterFlags::ADJUST_COORDINATE_SPACE,
        binding_map: Default::default(),
        zero_initialize_workgroup_memory: false,
    };
    let pipeline =
        glsl::PipelineOptions { shader_stage: stage, entry_point: entry.to_string(), multiview: None };
    let mut source = String::new();
    let mut writer = glsl::Writer::new(&mut source, &module, &info, &options, &pipeline, Default::default())
        .map_err(|e| glsl_error(name, e))?;
    let reflection = writer.write().map_err(|e| glsl_error(name, e))?;
    let binding = |handle: naga::Handle<naga::GlobalVariable>, name: &str| {
        let b = module.global_variables[handle].binding.as_ref();
        Binding {
            name: name.to_string(),
            group: b.map_or(0, |b| b.group),
            binding: b.map_or(0, |b| b.binding),
        }
    };
    let mut blocks: Vec<Binding> = reflection.uniforms.iter().map(|(h, n)| binding(*h, n)).collect();
    let mut textures: Vec<Binding> =
        reflection.texture_mapping.iter().map(|(n, m)| binding(m.texture, n)).collect();
    blocks.sort_by(|a, b| a.name.cmp(&b.name));
    textures.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(GlslStage { source, blocks, textures })
}

/// A program of `wgsl`'s entry points `vertex` and `fragment`, with `constants` written in.
pub fn program(
    name: &str,
    wgsl: &str,
    vertex: &str,
    fragment: &str,
    constants: &[(&str, f64)],
) -> Result<GlslProgram> {
    let (module, info) = parse(name, wgsl)?;
    Ok(GlslProgram {
        name: name.to_string(),
        vertex: stage(name, &module, &info, naga::ShaderStage::Vertex, vertex, constants)?,
        fragment: stage(name, &module, &info, naga::ShaderStage::Fragment, fragment, constants)?,
    })
}
