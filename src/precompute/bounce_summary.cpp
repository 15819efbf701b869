#include "precompute/bounce_summary.h"

#include <string>

#include "core/log.h"
#include "core/text.h"
#include "precompute/bounce_senders.h"

namespace prt {

void ReportBounces(const TransportReport& r, int channels) {
  std::string bounces = "bounces: ";
  for (std::size_t b = 0; b < r.bounce_share.size(); ++b) bounces += Formatted(b ? ", %.3g" : "%.3g", r.bounce_share[b]);
  if (r.bounce_share.empty()) bounces += "none";
  bounces += " of the direct energy; " + r.bounce_stop + Formatted(" [%.3f s]", r.bounce_seconds);
  if (channels == 3) bounces += "; coloured albedo: one transport vector per colour channel";
  if (r.senders.done)
    bounces += "; triangles with edges longer than " + Formatted("%.3g", double(r.senders.max_edge)) + " (" +
               Formatted("%g", 100.0 * kSenderEdge) +
               "% of the scene's diagonal) split for the bounces only, so the light a bounce reads does not "
               "depend on how coarsely the mesh is triangulated (" + std::to_string(r.senders.vertices_added) +
               " vertices added, not in the output)";
  Summary(bounces);
  if (r.senders.needed && !r.senders.done)
    Warn("bounces: the mesh has edges longer than " + Formatted("%.3g", double(r.senders.max_edge)) + " (" +
         Formatted("%g", 100.0 * kSenderEdge) + "% of its diagonal), and splitting them for the bounces would make " +
         Formatted("about %.2g", double(r.senders.triangles_estimate)) +
         " triangles: the light a bounce reads from such a large triangle is interpolated from its corners and "
         "can be far off inside it (split the mesh with --max-edge " + Formatted("%g", 100.0 * kSenderEdge) +
         "%, or in the modeller)");
}

}  // namespace prt
