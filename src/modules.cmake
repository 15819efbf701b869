# The folders of src/ (and bench/), each with the folders its files may include besides its own.
# Dependencies point one way: every folder is listed after the folders it includes, so the table
# has no cycle. scripts/check-includes.cmake reads every #include against it on every build (the
# `check_includes` target) and fails on one the table does not allow, on a folder the table does
# not list, on a cycle, and on a dependency no file uses (so the table stays true);
# docs/ARCHITECTURE.md draws it.
set(PRT_MODULES
  "core:"
  "texture: core"
  "sh: core"
  "geometry: core texture"
  "material: core sh"
  "io: core texture geometry material"
  "env: core sh io"
  "precompute: core texture sh geometry material env"
  "cpca: core sh geometry material precompute"
  "precompute_io: core texture sh geometry material precompute cpca"
  "farm: core precompute precompute_io"
  "raster: core texture sh"
  "options: core"
  "basis: core sh geometry env precompute cpca raster options"
  "sh_basis: core sh geometry material precompute cpca precompute_io raster basis"
  "wavelet: core sh geometry env precompute precompute_io raster basis options"
  "bases: options basis sh_basis wavelet"
  "video: core io"
  "render: core sh geometry io env raster basis video"
  "view: core io raster render"
  "report: core sh geometry io material env precompute cpca raster basis sh_basis bases render"
  "app: core texture sh geometry io material env precompute cpca precompute_io farm raster options basis sh_basis bases video render view report"
  "bench: core sh geometry io material env precompute cpca precompute_io raster options sh_basis wavelet render app"
  "cli: core options app bench"
)
