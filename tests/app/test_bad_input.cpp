// Bad input through the program, as a user meets it: every fixture of tests/data (one per
// failure mode, made by tests/data/make_fixtures.py) gives exit 1 (2 for usage errors) and
// exactly one stderr line `prt: error: <path or option>: <problem> (<expected>)`; never a
// signal, a hang or a stack trace. Valid oddities (1x1 faces, 16-bit and grey PNGs, extreme
// texels, relative indices, 100-gons) succeed.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "io/png_io.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

using test::Q;

std::vector<std::string> ErrorLines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("prt: error: ", 0) == 0) lines.push_back(line);
  return lines;
}

/// Runs prt with `arguments`; expects `exit_code` and exactly one error line that contains
/// every string of `parts`. Usage errors (exit 2) must point to `prt help COMMAND`.
void ExpectFailure(const std::string& arguments, int exit_code, const std::vector<std::string>& parts) {
  const auto r = test::RunPrt(arguments);
  CAPTURE(arguments);
  CAPTURE(r.err);
  CHECK(r.exit_code == exit_code);
  const auto lines = ErrorLines(r.err);
  REQUIRE(lines.size() == 1);
  for (const auto& part : parts) CHECK(lines[0].find(part) != std::string::npos);
  if (exit_code == 2) CHECK(lines[0].find("(see prt help") != std::string::npos);
  CHECK(r.err.find("terminate") == std::string::npos);
  CHECK(r.err.find("internal error") == std::string::npos);
}

void ExpectSuccess(const std::string& arguments) {
  const auto r = test::RunPrt(arguments);
  CAPTURE(arguments);
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  CHECK(ErrorLines(r.err).empty());
}

/// `prt light` on an environment (image file, cubemap folder or built-in name).
std::string Light(const std::string& env) { return "light --lmax 1 --env " + Q(env); }

/// `prt precompute` of a mesh under the furnace (closed form: no rays, fast).
std::string Precompute(const std::string& mesh, const std::string& out) {
  return "precompute --env furnace --transport unshadowed --mesh " + Q(mesh) + " --out " + Q(out);
}

std::string Image(const std::string& name) { return test::Fixture("images/" + name); }
std::string Obj(const std::string& name) { return test::Fixture("obj/" + name); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("bad input: missing files, folders where files belong, unreadable files") {
    const std::string dir = test::ScratchDir("bad_input_files");
    ExpectFailure(Light(dir + "/nope.hdr"), 1, {dir + "/nope.hdr", "no such file"});
    ExpectFailure(Precompute(dir + "/nope.obj", dir + "/out"), 1, {dir + "/nope.obj: no such file"});
    fs::create_directories(dir + "/folder.obj");
    ExpectFailure(Precompute(dir + "/folder.obj", dir + "/out"), 1, {dir + "/folder.obj: is a directory"});
    fs::create_directories(dir + "/folder.hdr");  // a folder is read as a cubemap: no faces in it
    ExpectFailure(Light(dir + "/folder.hdr"), 1, {dir + "/folder.hdr: missing face 'posx'"});
    // --out naming a file: the output folder cannot be made.
    std::ofstream(dir + "/a_file") << "x";
    ExpectFailure(Precompute(Obj("quad.obj"), dir + "/a_file"), 1, {dir + "/a_file"});

  }

  TEST_CASE("bad input: files the user may not read") {
    // chmod 000 keeps out everyone but root. As root (CI), prt runs as nobody (util-linux's
    // setpriv, on every Debian system), from a copy of the binary in a fresh folder under /tmp
    // that nobody can reach and write.
    char folder[] = "/tmp/prt-unreadable-XXXXXX";
    REQUIRE(::mkdtemp(folder) != nullptr);
    const std::string dir = folder;
    fs::permissions(dir, fs::perms::all);
    std::string prt = Q(test::PrtBinary());
    if (::geteuid() == 0) {
      fs::copy_file(test::PrtBinary(), dir + "/prt");
      fs::permissions(dir + "/prt", fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
      prt = "setpriv --reuid=65534 --regid=65534 --clear-groups " + Q(dir + "/prt");
    }
    const std::string locked = dir + "/locked.png";
    fs::copy_file(Image("grey8.png"), locked);
    fs::permissions(locked, fs::perms::none);
    const auto image = test::RunCommand(prt + " light --env " + Q(locked));
    CAPTURE(image.err);
    CHECK(image.exit_code == 1);
    CHECK(image.err == "prt: error: " + locked + ": cannot open (Permission denied)\n");
    const std::string locked_obj = dir + "/locked.obj";
    fs::copy_file(Obj("quad.obj"), locked_obj);
    fs::permissions(locked_obj, fs::perms::none);
    const auto mesh = test::RunCommand(prt + " precompute --mesh " + Q(locked_obj) + " --out " + Q(dir + "/out"));
    CAPTURE(mesh.err);
    CHECK(mesh.exit_code == 1);
    CHECK(mesh.err.find("prt: error: " + locked_obj + ": cannot be opened: Permission denied (expected a readable OBJ "
                        "file)") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("bad input: empty, truncated and wrong-format images behind the right extension") {
    for (const char* ext : {"png", "jpg", "hdr", "exr"}) {
      ExpectFailure(Light(Image(std::string("empty.") + ext)), 1, {Image(std::string("empty.") + ext), "empty file"});
      ExpectFailure(Light(Image(std::string("text_as.") + ext)), 1, {Image(std::string("text_as.") + ext) + ": "});
      ExpectFailure(Light(Image(std::string("truncated.") + ext)), 1, {Image(std::string("truncated.") + ext) + ": "});
    }
    // Found by these fixtures: stb 2.27 decoded a truncated flat .hdr from garbage, and looped
    // forever on a truncated RLE .hdr or on a run of length 0.
    ExpectFailure(Light(Image("truncated_flat.hdr")), 1, {"truncated or corrupt HDR image", "the file ends"});
    ExpectFailure(Light(Image("truncated.hdr")), 1, {"truncated or corrupt HDR image", "the file ends"});
    ExpectFailure(Light(Image("rle_zero_count.hdr")), 1, {"a run of length 0"});
  }

  TEST_CASE("bad input: headers claiming huge images are refused before any pixel is allocated") {
    // The files are under 100 bytes; decoding them would need gigabytes.
    ExpectFailure(Light(Image("huge_16384x16384.png")), 1, {"16384x16384 is too large", "at most 16384 per side"});
    ExpectFailure(Light(Image("huge_40000x20000.png")), 1, {"40000x20000 is too large"});
    ExpectFailure(Light(Image("huge_20000x1.exr")), 1, {"20000x1 is too large"});
    ExpectFailure(Light(test::Fixture("cubemaps/face_16k")), 1, {"posx.png: face of 16384x16384 is too large", "at most 8192"});
  }

  TEST_CASE("bad input: cubemap folders") {
    ExpectFailure(Light(test::Fixture("cubemaps/missing_face")), 1, {"missing_face: missing face 'negy'"});
    ExpectFailure(Light(test::Fixture("cubemaps/mixed_sizes")), 1, {"posz.png: face is 4x4", "six faces of one size"});
    ExpectFailure(Light(test::Fixture("cubemaps/non_square")), 1, {"negx.png: face is 2x4", "square"});
    ExpectFailure(Light(test::Fixture("cubemaps/truncated_face")), 1, {"posy.png: truncated or corrupt"});
    ExpectSuccess(Light(test::Fixture("cubemaps/one_by_one")));
  }

  TEST_CASE("bad input: grey, grey+alpha, RGBA and 16-bit PNGs and extreme texels load") {
    for (const char* name : {"grey8.png", "grey_alpha8.png", "rgba8.png", "rgb16.png", "grey16.png", "valid.hdr", "valid.exr"})
      ExpectSuccess(Light(Image(name)));
    // NaN, +-Inf, negative and 1e30 texels are replaced with a warning, and the light is finite.
    for (const char* name : {"extreme_texels.exr", "extreme_1e30.hdr"}) {
      const auto r = test::RunPrt(Light(Image(name)));
      CAPTURE(name);
      CAPTURE(r.err);
      CHECK(r.exit_code == 0);
      CHECK(r.err.find("prt: warning: " + Image(name)) != std::string::npos);
      CHECK(r.out.find("nan") == std::string::npos);
      CHECK(r.out.find("inf") == std::string::npos);
    }
  }

  TEST_CASE("bad input: OBJ failure modes and valid oddities") {
    const std::string out = test::ScratchDir("bad_input_obj");
    struct Case {
      const char* fixture;
      const char* part;
    };
    for (const Case& c : {Case{"empty.obj", "no faces"}, Case{"binary.obj", "no faces"},
                          Case{"no_faces.obj", "no faces"}, Case{"truncated.obj", "fewer than 3 vertices"},
                          Case{"index_out_of_range.obj", "out of bounds"}, Case{"index_zero.obj", "zero value"},
                          Case{"negative_out_of_range.obj", "indices 1..3"},
                          Case{"nan_coordinate.obj", "'nan' is not finite"}, Case{"inf_coordinate.obj", "'inf' is not finite"},
                          Case{"all_degenerate.obj", "zero area"}}) {
      ExpectFailure(Precompute(Obj(c.fixture), out), 1, {Obj(c.fixture) + ": ", c.part});
    }
    for (const char* name : {"negative_indices.obj", "polygon_100.obj", "huge_coordinates.obj", "duplicate_names.obj",
                             "some_degenerate.obj"})
      ExpectSuccess(Precompute(Obj(name), out));
    // A missing or unreadable .mtl is a warning: the default albedo applies.
    for (const char* name : {"missing_mtl.obj", "garbage_mtl.obj"}) {
      const auto r = test::RunPrt(Precompute(Obj(name), out));
      CAPTURE(r.err);
      CHECK(r.exit_code == 0);
      CHECK(r.err.find("prt: warning: " + Obj(name)) != std::string::npos);
    }
    // 1e7 coordinates render too (the camera frames them).
    ExpectSuccess("render --env furnace --transport unshadowed --frames 1 --size 16x16 --mesh " +
                  Q(Obj("huge_coordinates.obj")) + " --out " + Q(out + "/frames"));
  }

  TEST_CASE("bad input: every numeric option out of range, unknown and conflicting options, missing values") {
    const std::string out = test::ScratchDir("bad_input_options");
    const std::string render = "render --env furnace --transport unshadowed --out " + Q(out) + " ";
    struct Case {
      const char* args;
      const char* part;
    };
    for (const Case& c : {
             Case{"--lmax -1", "--lmax: '-1' is out of range (expected an integer from 0 to 64, or auto)"},
             Case{"--lmax 65", "--lmax: '65' is out of range"},
             Case{"--lmax 2.5", "--lmax: '2.5'"},
             Case{"--samples 0", "--samples: '0' is out of range"},
             Case{"--frames 0", "--frames: '0' is out of range"},
             Case{"--frames -3", "--frames: '-3'"},
             Case{"--frames 1e99", "--frames: '1e99'"},
             Case{"--size 0x10", "--size: '0x10'"},
             Case{"--size 16385x10", "--size: '16385x10'"},
             Case{"--size 10x16385", "--size: '10x16385'"},
             Case{"--size 64", "--size: '64'"},
             Case{"--threads 0", "--threads: '0' is out of range"},
             Case{"--bounces 0", "--bounces: '0'"},
             Case{"--direction-sets 0", "--direction-sets: '0'"},
             Case{"--ssaa 0", "--ssaa: '0'"},
             Case{"--ssaa 9", "--ssaa: '9'"},
             Case{"--exposure nan", "--exposure: 'nan'"},
             Case{"--exposure 21", "--exposure: '21'"},
             Case{"--fov 180", "--fov: '180'"},
             Case{"--seed -1", "--seed: '-1'"},
             Case{"--turns inf", "--turns: 'inf'"},
             Case{"--albedo 2,0,0", "--albedo"},
             Case{"--albedo 1,2", "--albedo: '1,2' is not three numbers"},
             Case{"--axis 0,0,0", "--axis"},
             Case{"--background 1,-1,0", "--background"},
             Case{"--sampler sideways", "--sampler: unknown value 'sideways'"},
             Case{"--tonemap film", "--tonemap: unknown value 'film'"},
             Case{"--view transport:x", "--view"},
             Case{"--view transport", "--view: unknown value 'transport' (expected radiance,"},  // the coefficient is not optional
             Case{"--view lite", "--view: unknown value 'lite' (did you mean light? expected radiance, irradiance,"},
             Case{"--view Radiance", "--view: unknown value 'Radiance' (did you mean radiance? expected"},
             Case{"--view glow", "--view: unknown value 'glow' (did you mean glossy? expected"},
             // Nothing near enough; every view named, transport with its coefficient.
             Case{"--view xyz", "--view: unknown value 'xyz' (expected radiance, irradiance, albedo, transport:K, light "
                                "or glossy)"},
             Case{"--look cose", "--look: unknown value 'cose' (did you mean course? expected one of default, course)"},
             Case{"--no-such-option 3", "--no-such-option: unknown option"},
             Case{"stray", "'stray': unexpected argument"},
             Case{"--frames 2 --frames 3", "--frames: given twice"},
             Case{"--quiet=yes", "--quiet: takes no value"},
             Case{"--size 16384x16384 --ssaa 2", "--ssaa"},              // conflicting: too many samples
             Case{"--lmax 2 --view transport:20", "--view: transport:20"},  // conflicting: no such coefficient
             Case{"--frames", "--frames: missing value"},
             Case{"--frames --size 8x8", "--frames: missing value"},
             Case{"--mesh=", "--mesh: empty value"},
         }) {
      ExpectFailure(render + c.args, 2, {c.part});
    }
    ExpectFailure("light --lmax 201", 2, {"--lmax: '201' is out of range (expected an integer from 0 to 200", "(see prt help light)"});
    ExpectFailure("light --frames 3", 2, {"--frames: unknown option"});
    ExpectFailure("no-such-command", 2, {"'no-such-command': unknown command"});
    ExpectFailure("light --env sky:sun=-1", 2, {"--env: sky:sun=-1: sun '-1' is out of range", "prt help light"});
    ExpectFailure("light --env no_such_environment", 1, {"no_such_environment: no such file, folder or built-in"});
  }

  TEST_CASE("bad input: a damaged transport cache is ignored with a note, recomputed and replaced") {
    const std::string out = test::ScratchDir("bad_input_cache");
    const std::string cache = out + "/transport.cache";
    const std::string run = "render --env furnace --transport shadowed --samples 16 --frames 1 --size 16x16 --mesh " +
                            Q(Obj("tetra_no_normals.obj")) + " --out " + Q(out);
    const auto first = test::RunPrt(run);
    REQUIRE(first.exit_code == 0);
    std::string good;
    {
      std::ifstream in(cache, std::ios::binary);
      good.assign(std::istreambuf_iterator<char>(in), {});
    }
    REQUIRE(good.size() > 48);
    auto damaged = [&](std::size_t offset, char x) {
      std::string bytes = good;
      bytes[offset] = static_cast<char>(bytes[offset] ^ x);
      return bytes;
    };
    struct Case {
      std::string what;
      std::string bytes;
      const char* reason;
    };
    std::string text;
    {
      std::ifstream in(test::Fixture("cache/text.cache"), std::ios::binary);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::vector<Case> cases = {
        {"truncated", good.substr(0, good.size() - 7), "truncated"},
        {"header only", good.substr(0, 48), "truncated"},
        {"a few bytes", good.substr(0, 5), "not a prt cache file"},
        {"empty", "", "not a prt cache file"},
        {"bit flip in the payload", damaged(good.size() - 3, 0x10), "checksum mismatch"},
        {"bit flip in the magic", damaged(2, 0x01), "not a prt cache file"},
        {"other format version", damaged(8, 0x03), "cache format version"},
        {"other inputs (key)", damaged(35, 0x40), "other inputs"},
        {"vertex count", damaged(30, 0x40), "corrupt header"},
        {"wrong format", text, "not a prt cache file"},
    };
    for (const Case& c : cases) {
      CAPTURE(c.what);
      { std::ofstream(cache, std::ios::binary | std::ios::trunc) << c.bytes; }
      const auto r = test::RunPrt(run);
      CAPTURE(r.err);
      CHECK(r.exit_code == 0);
      CHECK(ErrorLines(r.err).empty());
      CHECK(r.err.find("cache: " + cache + " ignored (") != std::string::npos);
      CHECK(r.err.find(c.reason) != std::string::npos);
      // Recomputed and rewritten: the next run takes it.
      const auto again = test::RunPrt(run);
      CHECK(again.err.find("taken from the cache") != std::string::npos);
    }
    // Other options (a different seed) make a different key: ignored, not trusted.
    const auto other = test::RunPrt(run + " --seed 7");
    CHECK(other.exit_code == 0);
    CHECK(other.err.find("made from other inputs") != std::string::npos);
    // A cache path that is a folder cannot be used: the cache is an optimisation, so a warning
    // naming it, and the frames are still written.
    fs::remove(cache);
    fs::create_directories(cache);
    const auto folder = test::RunPrt(run);
    CHECK(folder.exit_code == 0);
    CHECK(folder.err.find("prt: warning: cache: " + cache + ": is a folder (expected a file name); going on without "
                           "the cache") != std::string::npos);
    CHECK(fs::exists(out + "/frame_0000.png"));
  }

  TEST_CASE("bad input: textures (--texture and map_Kd) before any work") {
    const std::string dir = test::ScratchDir("bad_texture");
    {
      std::ofstream obj(dir + "/square.obj");
      obj << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
      std::ofstream bad(dir + "/bad.png");
      bad << "not a png";
    }
    const std::string render = "render --frames 1 --size 8x8 --env furnace --transport unshadowed --out " + Q(dir + "/out");
    ExpectFailure(render + " --mesh " + Q(dir + "/square.obj") + " --texture " + Q(dir + "/none.png"), 1,
                  {dir + "/none.png", "no such file"});
    ExpectFailure(render + " --mesh " + Q(dir + "/square.obj") + " --texture " + Q(dir + "/bad.png"), 1,
                  {dir + "/bad.png"});
    ExpectFailure(render + " --mesh " + Q(dir + "/square.obj") + " --texture " + Q(dir), 1, {dir});
    ExpectFailure(render + " --texture " + Q(Image("rgba8.png")), 2, {"--texture", "needs --mesh"});
    ExpectFailure(render + " --mesh " + Q(dir + "/square.obj") + " --texture " + Q(Image("rgba8.png")) +
                      " --albedo 0.5,0.5,0.5", 2, {"--texture and --albedo"});
    ExpectFailure(render + " --mesh " + Q(Obj("tetra_no_normals.obj")) + " --texture " + Q(Image("rgba8.png")), 1,
                  {"tetra_no_normals.obj", "no texture coordinates"});
    CHECK(!fs::exists(dir + "/out/frame_0000.png"));
    ExpectSuccess(render + " --mesh " + Q(dir + "/square.obj") + " --texture " + Q(Image("rgba8.png")));
  }

  TEST_CASE("bad input: one face of a cubemap as --env is refused before any work (pass the folder)") {
    const std::string dir = test::ScratchDir("cube_face_env");
    const std::string cube = dir + "/GraceCathedral", lone = dir + "/lone";
    fs::create_directories(cube);
    fs::create_directories(lone);
    Image8 square(4, 4);  // grey
    for (auto& v : square.rgb) v = 128;
    for (const char* face : {"posx", "negx", "posy", "negy", "posz", "negz"}) WritePng(cube + "/" + face + ".png", square);
    const std::string out = dir + "/out";
    const std::string render = "render --frames 1 --size 8x8 --transport unshadowed --mesh " + Q(Obj("quad.obj")) +
                               " --out " + Q(out) + " --env ";
    const auto r = test::RunPrt(render + Q(cube + "/posx.png"));
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    // The one line says which face it is and the folder to pass instead.
    CHECK(r.err == "prt: error: " + cube + "/posx.png: is the posx face of the cubemap in " + cube +
                       " (expected the folder: --env " + cube + ")\n");
    // Refused by the early input check: no output folder made, no mesh read (a check only at the
    // environment's loading would come after both).
    CHECK_FALSE(fs::exists(out));
    ExpectFailure(Light(cube + "/negz.png"), 1, {"is the negz face", "--env " + cube});
    // The folder itself is the cubemap; a lone square posx.png beside nothing is an image.
    ExpectSuccess(Light(cube));
    WritePng(lone + "/posx.png", square);
    ExpectSuccess(render + Q(lone + "/posx.png"));
    CHECK(fs::exists(out + "/frame_0000.png"));
  }
}

}  // namespace prt
