#include "poll_qr.h"

#include <qrcodegen/qrcodegen.hpp>

QrModules qrModules(const std::string& text) {
    const qrcodegen::QrCode code =
        qrcodegen::QrCode::encodeText(text.c_str(), qrcodegen::QrCode::Ecc::MEDIUM);
    QrModules m;
    m.size = code.getSize();
    m.dark.resize(static_cast<std::size_t>(m.size * m.size));
    for (int y = 0; y < m.size; ++y)
        for (int x = 0; x < m.size; ++x)
            m.dark[static_cast<std::size_t>(y * m.size + x)] = code.getModule(x, y);
    return m;
}
