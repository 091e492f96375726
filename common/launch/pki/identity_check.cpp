// The identity check of a run's security material (launch/pki/identity_check.hpp), with OpenSSL.
#include "launch/pki/identity_check.hpp"

#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>

#include <memory>
#include <string>

#include "config/config.hpp"
#include "dds/security/security.hpp"

namespace gdnav::launch::pki {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
    throw config::ConfigError("security error: " + file.string() + ": " + what);
}

std::string ssl_error() {
    const unsigned long e = ERR_get_error();
    if (e == 0) return "unknown OpenSSL error";
    char buf[256];
    ERR_error_string_n(e, buf, sizeof buf);
    ERR_clear_error();
    return buf;
}

struct BioFree { void operator()(BIO* b) const { BIO_free(b); } };
struct X509Free { void operator()(X509* x) const { X509_free(x); } };
struct KeyFree { void operator()(EVP_PKEY* k) const { EVP_PKEY_free(k); } };
struct StoreFree { void operator()(X509_STORE* s) const { X509_STORE_free(s); } };
struct CtxFree { void operator()(X509_STORE_CTX* c) const { X509_STORE_CTX_free(c); } };
struct Pkcs7Free { void operator()(PKCS7* p) const { PKCS7_free(p); } };
using Bio = std::unique_ptr<BIO, BioFree>;
using Cert = std::unique_ptr<X509, X509Free>;

Bio open_file(const fs::path& file) {
    if (!fs::is_regular_file(file)) fail(file, "missing (make the directory with `gdnav pki init DIR --scenario S`)");
    Bio b(BIO_new_file(file.c_str(), "r"));
    if (!b) fail(file, "cannot be opened: " + ssl_error());
    return b;
}

Cert load_cert(const fs::path& file) {
    Bio b = open_file(file);
    Cert c(PEM_read_bio_X509(b.get(), nullptr, nullptr, nullptr));
    if (!c) fail(file, "not a PEM certificate: " + ssl_error());
    return c;
}

std::unique_ptr<X509_STORE, StoreFree> store_with(X509* ca) {
    std::unique_ptr<X509_STORE, StoreFree> s(X509_STORE_new());
    X509_STORE_add_cert(s.get(), ca);
    return s;
}

// Verifies an S/MIME document (as `openssl smime -sign` writes it) against the CA; returns the signed text.
std::string verify_signed(const fs::path& file, X509* ca) {
    Bio b = open_file(file);
    BIO* content_raw = nullptr;
    std::unique_ptr<PKCS7, Pkcs7Free> p7(SMIME_read_PKCS7(b.get(), &content_raw));
    Bio content(content_raw);
    if (!p7) fail(file, "not an S/MIME signed document: " + ssl_error());
    auto store = store_with(ca);
    Bio out(BIO_new(BIO_s_mem()));
    if (PKCS7_verify(p7.get(), nullptr, store.get(), content.get(), out.get(), PKCS7_TEXT) != 1)
        fail(file, "signature does not verify against ca.pem: " + ssl_error());
    char* data = nullptr;
    const long n = BIO_get_mem_data(out.get(), &data);
    return std::string(data, static_cast<std::size_t>(n));
}

}  // namespace

void check_identity(const fs::path& dir, const std::string& identity) {
    if (!fs::is_directory(dir)) fail(dir, "not a directory (make it with `gdnav pki init DIR --scenario S`)");
    const fs::path ca_file = dir / "ca.pem";
    const fs::path cert_file = dir / "identities" / (identity + ".pem");
    const fs::path key_file = dir / "identities" / (identity + ".key");
    Cert ca = load_cert(ca_file);
    Cert cert = load_cert(cert_file);

    auto store = store_with(ca.get());
    std::unique_ptr<X509_STORE_CTX, CtxFree> ctx(X509_STORE_CTX_new());
    X509_STORE_CTX_init(ctx.get(), store.get(), cert.get(), nullptr);
    if (X509_verify_cert(ctx.get()) != 1) {
        const int err = X509_STORE_CTX_get_error(ctx.get());
        fail(cert_file, std::string("certificate rejected: ") + X509_verify_cert_error_string(err) +
                            " (against " + ca_file.string() + ")");
    }
    Bio name_out(BIO_new(BIO_s_mem()));
    X509_NAME_print_ex(name_out.get(), X509_get_subject_name(cert.get()), 0, XN_FLAG_RFC2253);
    char* name_data = nullptr;
    const std::string subject(name_data, static_cast<std::size_t>(BIO_get_mem_data(name_out.get(), &name_data)));
    if (subject != dds::security::subject_name(identity))
        fail(cert_file, "subject is '" + subject + "', expected '" + dds::security::subject_name(identity) + "'");

    Bio kb = open_file(key_file);
    std::unique_ptr<EVP_PKEY, KeyFree> key(PEM_read_bio_PrivateKey(kb.get(), nullptr, nullptr, nullptr));
    if (!key) fail(key_file, "not a PEM private key: " + ssl_error());
    if (X509_check_private_key(cert.get(), key.get()) != 1) fail(key_file, "does not match " + cert_file.string());

    verify_signed(dir / "governance.p7s", ca.get());
    const std::string permissions = verify_signed(dir / "permissions.p7s", ca.get());
    if (permissions.find("<subject_name>" + dds::security::subject_name(identity) + "</subject_name>") ==
        std::string::npos)
        fail(dir / "permissions.p7s", "no grant for identity '" + identity + "' (re-run gdnav pki init with it)");
}

}  // namespace gdnav::launch::pki
