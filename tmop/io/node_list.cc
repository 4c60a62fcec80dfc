#include "tmop/io/node_list.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tmop/io/scanner.h"

namespace tmop {

Status read_node_list(const std::string& path, int num_vertices, std::vector<char>* flags) {
  try {
    io::check_regular_file(path);
  } catch (const Error& e) {
    return Status::Failure(e.what());
  }
  std::ifstream in(path);
  if (!in) return Status::Failure(path + ": cannot open (" + std::strerror(errno) + ")");
  flags->assign(static_cast<std::size_t>(num_vertices), 0);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t hash = line.find('#');
    std::istringstream words(line.substr(0, hash));
    std::string w;
    while (words >> w) {
      const std::string place = path + ":" + std::to_string(number) + ": ";
      std::size_t used = 0;
      long long v = -1;
      try {
        v = std::stoll(w, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != w.size() || w[0] == '+')
        return Status::Failure(place + "'" + io::printable(w) + "' is not a node index");
      if (v < 0 || v >= num_vertices)
        return Status::Failure(place + "node " + w + " out of range 0.." +
                               std::to_string(num_vertices - 1));
      (*flags)[static_cast<std::size_t>(v)] = 1;
    }
  }
  if (in.bad()) return Status::Failure(path + ": read error");
  return Status::Ok();
}

Status node_flags_from_field(const Mesh& mesh, const std::string& name, std::vector<char>* flags) {
  std::string names;
  for (const DataArray& a : mesh.point_data) {
    if (a.name == name) {
      flags->assign(static_cast<std::size_t>(mesh.num_vertices()), 0);
      const std::size_t c = static_cast<std::size_t>(std::max(1, a.components));
      for (std::size_t i = 0; i < a.values.size() && i / c < flags->size(); ++i)
        if (a.values[i] != 0) (*flags)[i / c] = 1;
      return Status::Ok();
    }
    names += (names.empty() ? "" : ", ") + a.name;
  }
  return Status::Failure("no point-data array '" + name +
                         "' (arrays: " + (names.empty() ? std::string("none") : names) + ")");
}

}  // namespace tmop
