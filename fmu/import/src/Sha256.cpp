// fileSha256 (fmuImport.hpp) with OpenSSL's libcrypto, through its EVP
// interface.
#include "fmuImport/fmuImport.hpp"

#include <openssl/evp.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <vector>

namespace fmuImport {

std::string fileSha256(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read '" + path
                    + "' for its SHA-256: " + std::strerror(errno));
    const std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> context(
        EVP_MD_CTX_new(), EVP_MD_CTX_free);
    if (!context
        || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
        throw Error("cannot compute the SHA-256 of '" + path
                    + "': OpenSSL's SHA-256 is not available");
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        if (in.gcount() > 0
            && EVP_DigestUpdate(context.get(), buffer.data(),
                                static_cast<std::size_t>(in.gcount()))
                != 1)
            throw Error("cannot compute the SHA-256 of '" + path + "'");
    }
    if (in.bad())
        throw Error("cannot read '" + path + "' for its SHA-256");
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    if (EVP_DigestFinal_ex(context.get(), digest, &size) != 1)
        throw Error("cannot compute the SHA-256 of '" + path + "'");
    static const char* const hex = "0123456789abcdef";
    std::string text;
    for (unsigned int i = 0; i < size; ++i) {
        text += hex[digest[i] >> 4];
        text += hex[digest[i] & 15];
    }
    return text;
}

} // namespace fmuImport
