"""Run inside Blender (``blender -b --factory-startup --python THIS -- JOB.json``): Freestyle's
lines of a mesh from a list of cameras, lines only, one PNG per camera.

Blender's own Python runs this file, without NumPy or toonmesh; :mod:`toonmesh.bench._freestyle`
writes the job and reads the frames. The job (JSON): ``obj`` (the mesh, in toonmesh's world
coordinates), ``out`` (a folder), ``size`` (pixels, square), ``cameras`` (per frame: ``matrix``,
camera to world, 4x4 rows; ``fov_y``, vertical, degrees; ``clip``, [near, far]), ``thickness``
(the lines' width in pixels), ``suggestive`` (bool: also suggestive contours), ``engine``
("BLENDER_EEVEE" or "CYCLES") and ``samples``. It writes ``frame_NNNN.png`` per camera and
``report.json``: Blender's version, the engine and each frame's render seconds.
"""

import json
import math
import os
import sys
import time

import bpy
from mathutils import Matrix


def load_mesh(path):
    # identity axes: the file's coordinates are the scene's, as toonmesh's cameras expect
    bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    obj = bpy.context.selected_objects[0]
    for polygon in obj.data.polygons:  # smooth normals, as toonmesh draws the bunny
        polygon.use_smooth = True
    # lines only: the surface is a holdout (alpha 0), while Freestyle still sees it and hides
    # the lines behind it
    material = bpy.data.materials.new("holdout")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(nodes.new("ShaderNodeHoldout").outputs[0], output.inputs["Surface"])
    obj.data.materials.append(material)
    return obj


def camera(scene):
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    obj = bpy.data.objects.new("camera", data)
    scene.collection.objects.link(obj)
    scene.camera = obj
    return obj


def place(cam, view):
    cam.matrix_world = Matrix(view["matrix"])
    cam.data.angle_y = math.radians(view["fov_y"])
    cam.data.clip_start, cam.data.clip_end = view["clip"]


def freestyle(scene, thickness, suggestive):
    render = scene.render
    render.use_freestyle = True
    render.line_thickness_mode = "ABSOLUTE"
    render.line_thickness = 1.0
    layer = scene.view_layers[0]
    layer.use_freestyle = True
    settings = layer.freestyle_settings
    settings.mode = "EDITOR"
    settings.use_smoothness = True  # contours of the smooth surface, not of its faces
    for old in list(settings.linesets):
        settings.linesets.remove(old)
    lineset = settings.linesets.new("Smooth")
    lineset.select_by_visibility = True
    lineset.visibility = "VISIBLE"
    lineset.select_by_edge_types = True
    for kind in ("silhouette", "border", "crease"):
        setattr(lineset, "select_" + kind, True)
    lineset.select_suggestive_contour = bool(suggestive)
    style = bpy.data.linestyles.new("ink")
    style.color = (0.0, 0.0, 0.0)
    style.alpha = 1.0
    style.thickness = thickness
    style.thickness_position = "CENTER"
    lineset.linestyle = style


def main():
    job = json.load(open(sys.argv[sys.argv.index("--") + 1]))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    load_mesh(job["obj"])
    cam = camera(scene)
    render = scene.render
    render.engine = job["engine"]
    if job["engine"] == "CYCLES":
        scene.cycles.device = "CPU"
        scene.cycles.samples = job["samples"]
        scene.cycles.use_denoising = False  # Debian's build has no denoiser; lines need none
    else:
        scene.eevee.taa_render_samples = job["samples"]
    render.resolution_x = render.resolution_y = job["size"]
    render.resolution_percentage = 100
    render.film_transparent = True
    render.image_settings.file_format = "PNG"
    render.image_settings.color_mode = "RGBA"
    freestyle(scene, job["thickness"], job["suggestive"])
    seconds = []
    for i, view in enumerate(job["cameras"]):
        place(cam, view)
        render.filepath = os.path.join(job["out"], "frame_%04d.png" % i)
        t0 = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        seconds.append(time.perf_counter() - t0)
    with open(os.path.join(job["out"], "report.json"), "w") as f:
        json.dump({"version": bpy.app.version_string, "engine": render.engine, "seconds": seconds}, f)


main()
