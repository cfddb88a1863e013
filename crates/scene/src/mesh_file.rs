//! Triangle meshes read from files: Wavefront OBJ (`tobj`) and STL, binary or ASCII (`stl_io`).

use std::path::Path;
use tether_physics::math::Vec3;

/// Vertices [file units] and triangles of a mesh file. Coordinates are single precision, as
/// STL files store them (OBJ text is read to `f32` too, see Cargo.toml).
pub type TriangleList = (Vec<Vec3>, Vec<[u32; 3]>);

/// Reads the mesh at `path`, chosen by its extension (`.obj` or `.stl`, any case); every
/// object of an OBJ file is kept, polygons are triangulated, materials are ignored.
///
/// # Errors
/// A message naming what went wrong: unknown extension, unreadable or malformed file.
pub fn read(path: &Path) -> Result<TriangleList, String> {
    let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("obj") => read_obj(path),
        Some("stl") => read_stl(path),
        _ => Err(format!("mesh file {:?} must end in .obj or .stl", path.display().to_string())),
    }
}

fn read_obj(path: &Path) -> Result<TriangleList, String> {
    let file = std::fs::File::open(path)
        .map_err(|e| format!("cannot read mesh file {:?}: {e}", path.display().to_string()))?;
    let options =
        tobj::LoadOptions { triangulate: true, ignore_points: true, ignore_lines: true, ..Default::default() };
    let (models, _) =
        tobj::load_obj_buf(&mut std::io::BufReader::new(file), &options, |_| Err(tobj::LoadError::GenericFailure))
            .map_err(|e| format!("mesh file {:?} is not a valid OBJ file: {e}", path.display().to_string()))?;
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for model in &models {
        let offset = u32::try_from(vertices.len()).map_err(|_| "mesh file has too many vertices".to_string())?;
        vertices.extend(
            model.mesh.positions.chunks_exact(3).map(|p| Vec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))),
        );
        triangles.extend(model.mesh.indices.chunks_exact(3).map(|t| [t[0] + offset, t[1] + offset, t[2] + offset]));
    }
    Ok((vertices, triangles))
}

fn read_stl(path: &Path) -> Result<TriangleList, String> {
    let mut file = std::fs::File::open(path)
        .map_err(|e| format!("cannot read mesh file {:?}: {e}", path.display().to_string()))?;
    let mesh = stl_io::read_stl(&mut file)
        .map_err(|e| format!("mesh file {:?} is not a valid STL file: {e}", path.display().to_string()))?;
    let vertices =
        mesh.vertices.iter().map(|v| Vec3::new(f64::from(v.0[0]), f64::from(v.0[1]), f64::from(v.0[2]))).collect();
    let index = |i: usize| u32::try_from(i).map_err(|_| "mesh file has too many vertices".to_string());
    let triangles = mesh
        .faces
        .iter()
        .map(|f| Ok([index(f.vertices[0])?, index(f.vertices[1])?, index(f.vertices[2])?]))
        .collect::<Result<_, String>>()?;
    Ok((vertices, triangles))
}
