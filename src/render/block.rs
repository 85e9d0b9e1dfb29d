//! Uniform blocks: a `#[repr(C)]` Rust struct laid out byte for byte as the WGSL struct of the
//! same name, which a test holds against naga's reflection of the shaders (field order,
//! offsets, sizes). Blocks are 16-byte multiples, so that blocks can follow each other in the
//! frame's and draws' uniform structs (`uniforms.rs`) without padding between them.

/// A field of a block: its name, byte offset and size.
pub type FieldLayout = (&'static str, usize, usize);

/// How a block is laid out, for the layout test and the uniform structs that hold blocks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BlockLayout {
    /// The WGSL struct's name.
    pub wgsl: &'static str,
    pub size: usize,
    /// The fields, padding (names starting with `_`) left out.
    pub fields: Vec<FieldLayout>,
}

/// A uniform block.
pub trait Block: bytemuck::Pod {
    const WGSL: &'static str;
    fn fields() -> Vec<FieldLayout>;

    fn layout() -> BlockLayout {
        BlockLayout { wgsl: Self::WGSL, size: std::mem::size_of::<Self>(), fields: Self::fields() }
    }

    fn bytes(&self) -> Vec<u8> {
        bytemuck::bytes_of(self).to_vec()
    }
}

/// Defines a uniform block: the struct (Pod, zeroable, `#[repr(C)]`) and its `Block` layout.
/// Fields whose names start with `_` are padding.
#[macro_export]
macro_rules! uniform_block {
    (
        $(#[$meta:meta])*
        pub struct $name:ident as $wgsl:literal {
            $($(#[$fmeta:meta])* pub $field:ident : $ty:ty,)*
        }
    ) => {
        $(#[$meta])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
        pub struct $name {
            $($(#[$fmeta])* pub $field: $ty,)*
        }

        impl $crate::render::block::Block for $name {
            const WGSL: &'static str = $wgsl;
            fn fields() -> Vec<$crate::render::block::FieldLayout> {
                vec![$((stringify!($field), std::mem::offset_of!($name, $field), std::mem::size_of::<$ty>())),*]
                    .into_iter()
                    .filter(|f| !f.0.starts_with('_'))
                    .collect()
            }
        }
    };
}

/// `[x, y, z, 0]`: a colour or direction in a vec4 slot.
pub fn vec4(v: [f32; 3]) -> [f32; 4] {
    [v[0], v[1], v[2], 0.0]
}
