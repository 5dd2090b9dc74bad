#include "app/tracker_sim/malformed_datagrams.h"

namespace sandstorm {

std::string malformDatagram(const std::string& good, std::mt19937& random) {
  std::uniform_int_distribution<int> kind(0, 8);
  switch (kind(random)) {
    case 0: {  // truncated
      std::uniform_int_distribution<std::size_t> at(1, good.size() - 1);
      return good.substr(0, at(random));
    }
    case 1: {  // binary junk
      std::string junk(256, '\0');
      for (char& c : junk)
        c = char(random() & 0xff);
      return junk;
    }
    case 2:  // three bodies announced, one sent
      return "fr 1\r\n6d 3 [0 1.000][10 20 30][1 0 0 0 1 0 0 0 1]\r\n";
    case 3:
      return "fr 2\r\n6d 1 [0 1.000][nan 20 30][1 0 0 0 1 0 0 0 1]\r\n";
    case 4:
      return "fr 3\r\n6df2 1 1 [0 1.000 6 2][10 20 inf][1 0 0 0 1 0 0 0 1][1 0 0]\r\n";
    case 5:
      return "fr 4\r\n6d 1 [4000000000 1.000][10 20 30][1 0 0 0 1 0 0 0 1]\r\n";
    case 6:
      return "fr 5\r\n6d 99999999 [0 1.000][10 20 30][1 0 0 0 1 0 0 0 1]\r\n";
    case 7:  // a matrix that is no rotation
      return "fr 6\r\n6d 1 [0 1.000][10 20 30][1 1 1 1 1 1 1 1 1]\r\n";
    default:  // a 64 KiB wall of text
      return std::string(65000, '7');
  }
}

}  // namespace sandstorm
