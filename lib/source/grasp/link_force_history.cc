#include <algorithm>
#include <softgrasp/grasp/link_force_history.h>

namespace softgrasp
{
  double LinkForceHistory::largest_normal() const
  {
    return normal.empty() ? 0 : *std::max_element(normal.begin(), normal.end());
  }

  LinkForceHistory LinkForceHistory::since(const double start) const
  {
    LinkForceHistory kept;
    kept.link = link;
    for (std::size_t i = 0; i < time.size(); ++i)
      if (time[i] >= start - 1e-12)
      {
        kept.time.push_back(time[i] - start);
        kept.force.push_back(force[i]);
        for (auto [to, from] : {std::pair{&kept.normal, &normal},
                                {&kept.lateral, &lateral},
                                {&kept.friction, &friction},
                                {&kept.nodal_normal, &nodal_normal},
                                {&kept.closed, &closed},
                                {&kept.slipping, &slipping}})
          to->push_back((*from)[i]);
      }
    return kept;
  }

  std::vector<LinkForceHistory>
  link_force_histories(const RigidBodySet                    &bodies,
                       const std::vector<ContactForceRecord> &records)
  {
    std::vector<LinkForceHistory> links;
    for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
      {
        LinkForceHistory h;
        h.link = bodies.geom_label(b, g);
        for (const auto &record : records)
        {
          const GeomContactForce &f = record.forces.at(b).at(g);
          h.time.push_back(record.time);
          h.force.push_back(f.force);
          h.normal.push_back(f.normal_force());
          h.lateral.push_back(f.lateral_part.norm());
          h.friction.push_back(f.friction.norm());
          h.nodal_normal.push_back(f.nodal_normal);
          h.closed.push_back(f.active);
          h.slipping.push_back(f.slipping);
        }
        links.push_back(std::move(h));
      }
    return links;
  }
} // namespace softgrasp
