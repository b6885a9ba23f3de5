/*
 * Copyright (c) 2025-2026 Masahide Kashiwagi (kashi@waseda.jp)
 */

#ifndef KV_VERSION_HPP
#define KV_VERSION_HPP
#define KV_VERSION_MAJOR 0
#define KV_VERSION_MINOR 4
#define KV_VERSION_PATCHLEVEL 61
#define KV_VERSION_STRING "0.4.61"
#endif // KV_VERSION_HPP
