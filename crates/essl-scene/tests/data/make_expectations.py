#!/usr/bin/env python3
"""Regenerate the essl-scene test expectations from the reference tool.

usage: python3 make_expectations.py            # both sets below
       python3 make_expectations.py SCENES_DIR OUT_DIR [TOOL]

The two sets: the shared scenes (shared/scenes beside the repository) into shared/, and this
crate's own awkward test scenes (local-scenes/) into local/. TOOL defaults to
shared/tools/webgl2-render.py beside the repository.

For every SCENES_DIR/*.json this runs `webgl2-render.py SCENE -o PNG --dump DUMP` (headless
Chromium, Debian's chromium package) and writes OUT_DIR/SCENE_NAME.json, holding:
  dump        what --dump wrote, except the mesh: uniforms (active type, float32 values as
              JSON numbers, so the sign of a zero is lost), textures, attributes, depth_bits,
              index_type;
  mesh        a summary of the dump's mesh: vertex count; per stream its length, the FNV-1a
              64-bit hash of its float32 little-endian bytes, and the bits of its first and
              last 8 floats; the indices' count, FNV-1a 64 of them as u32 little-endian, first
              and last 12;
  mesh_full   the dump's whole mesh, only when it has at most 200 vertices;
  derived     every derived value (FORMAT.md's table) as float32 bit patterns ("0x3f800000"),
              computed with the tool's own functions in the tool's order (signs of zeros kept);
  derived_f64 the same before rounding: float64 bit patterns;
  mesh_f64    per stream, FNV-1a 64 of the float64 little-endian bytes the tool's build_mesh
              computes before rounding to float32, and its first 8 values' bits;
  texels      per texture: width, height, filter, wrap and FNV-1a 64 of the RGBA8 texels, from
              the tool's build_texture.
"""
import importlib.util, json, os, struct, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "..", "..", "..", "shared"))


def fnv1a64(data):
    h = 0xcbf29ce484222325
    for b in data:
        h ^= b
        h = (h * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def f32_bits(values):
    return [f"0x{struct.unpack('<I', struct.pack('<f', v))[0]:08x}" for v in values]


def f64_bits(values):
    return [f"0x{struct.unpack('<Q', struct.pack('<d', v))[0]:016x}" for v in values]


def main(argv):
    tool_path = argv[3] if len(argv) > 3 else os.path.join(SHARED, "tools", "webgl2-render.py")
    if len(argv) > 2:
        make(argv[1], argv[2], tool_path)
    else:
        make(os.path.join(SHARED, "scenes"), os.path.join(HERE, "shared"), tool_path)
        make(os.path.join(HERE, "local-scenes"), os.path.join(HERE, "local"), tool_path)


def make(scenes, out_dir, tool_path):
    os.makedirs(out_dir, exist_ok=True)
    spec = importlib.util.spec_from_file_location("webgl2_render", tool_path)
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    for file in sorted(os.listdir(scenes)):
        if not file.endswith(".json"):
            continue
        name = file[:-5]
        path = os.path.join(scenes, file)
        with tempfile.TemporaryDirectory() as tmp:
            dump_path = os.path.join(tmp, "dump.json")
            subprocess.run([sys.executable, tool_path, path, "-o", os.path.join(tmp, "out.png"), "--dump", dump_path],
                           check=True, stdout=subprocess.DEVNULL)
            with open(dump_path) as fh:
                dump = json.load(fh)
        mesh = dump.pop("mesh")
        indices = mesh.pop("indices")
        vertex_count = len(mesh["position"]) // 3 if "position" in mesh else None
        summary = {"vertex_count": vertex_count, "streams": {}, "indices": None}
        for stream, values in mesh.items():
            raw = struct.pack(f"<{len(values)}f", *values)
            summary["streams"][stream] = {"len": len(values), "fnv1a64": fnv1a64(raw),
                                          "head": f32_bits(values[:8]), "tail": f32_bits(values[-8:])}
        if indices is not None:
            summary["indices"] = {"count": len(indices), "fnv1a64_u32le": fnv1a64(struct.pack(f"<{len(indices)}I", *indices)),
                                  "head": indices[:12], "tail": indices[-12:]}

        with open(path) as fh:
            s = json.load(fh)
        cam = s["camera"]
        eye, target, up = ([float(v) for v in cam[k]] for k in ("eye", "target", "up"))
        m = s.get("model", {})
        m = {"translate": [float(v) for v in m.get("translate", [0, 0, 0])],
             "rotate_deg": [float(v) for v in m.get("rotate_deg", [0, 0, 0])],
             "scale": [float(v) for v in m.get("scale", [1, 1, 1])]}
        model = tool.model_matrix(m)
        view = tool.look_at_view(eye, target, up)
        projection = tool.perspective(float(cam["fov_y_deg"]), s["width"] / s["height"], float(cam["near"]), float(cam["far"]))
        view_projection = tool.mat_mul(projection, view)
        derived = {
            "model": model, "view": view, "projection": projection,
            "view_projection": view_projection,
            "model_view": tool.mat_mul(view, model),
            "model_view_projection": tool.mat_mul(view_projection, model),
            "model_inverse_transpose": tool.transpose(tool.inverse(model, "model")),
            "normal_matrix": tool.transpose(tool.inverse(tool.mat_mul(view, model), "normal_matrix")),
            "eye": eye, "viewport": [float(s["width"]), float(s["height"])],
        }
        texels = {}
        for tname, t in sorted(s.get("textures", {}).items()):
            import base64
            built = tool.build_texture(tname, t)
            texels[tname] = {"width": built["width"], "height": built["height"], "filter": built["filter"],
                             "wrap": built["wrap"], "fnv1a64": fnv1a64(base64.b64decode(built["data"]))}
        streams64, _ = tool.build_mesh(s["mesh"])
        mesh_f64 = {k: {"fnv1a64": fnv1a64(struct.pack(f"<{len(v)}d", *v)), "head": f64_bits(v[:8])}
                    for k, v in streams64.items()}
        out = {"scene": file, "dump": dump, "mesh": summary, "mesh_f64": mesh_f64,
               "derived": {k: f32_bits(v) for k, v in derived.items()},
               "derived_f64": {k: f64_bits(v) for k, v in derived.items()}, "texels": texels}
        if vertex_count is not None and vertex_count <= 200:
            out["mesh_full"] = {**mesh, "indices": indices}
        out_path = os.path.join(out_dir, name + ".json")
        with open(out_path, "w") as fh:
            json.dump(out, fh, indent=1)
            fh.write("\n")
        print(f"{out_path}: {os.path.getsize(out_path)} bytes")


if __name__ == "__main__":
    main(sys.argv)
