//! The presets: another library's filter reproduced, quirks included (`options::resolve`), or a
//! paper's rule as published (`denoise::resolve` for the guided filter), each with its name
//! (`described` lists which method has which).

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// No preset: distinct neighbours, rows that sum to one, boundaries as asked.
    Clean,
    Trimesh,
    Pymeshlab,
    /// Al-Rousan et al.: every vertex moves to the plain mean of its neighbours; for the guided
    /// filter, Zhang et al.'s rule as their code has it.
    Paper,
}

/// The presets by the name the API spells.
pub const PRESETS: [(&str, Preset); 3] =
    [("trimesh", Preset::Trimesh), ("pymeshlab", Preset::Pymeshlab), ("paper", Preset::Paper)];
